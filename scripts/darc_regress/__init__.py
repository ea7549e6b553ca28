"""darc-regress: golden-image regression suites for darc (see README.md, "Golden-image regression
suites"). One module per concept: suite (what to run, from regress.toml), render (running darc),
comparison (OIIO's compare and the verdict), preview_images (the PNGs of the report),
html_report, junit_report, and cli (arguments, parallel runs, --update, exit codes)."""
