"""darc-slurm: render a frame sequence with darc as a Slurm array job, resume it, and report which
frames are done, missing or failed (README.md, "Render farms"). One module per concept: frames
(darc's --frames lists and '#'/%04d names), farm_folder (the folder that holds a sequence's
definition, its jobs, logs and stats), task_script (the batch script each array task runs),
slurm (sbatch and squeue), frame_status (done / missing / failed from images and logs), and cli
(the submit and status commands, exit codes)."""
