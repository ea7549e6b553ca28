#!/usr/bin/python3
"""ctest slurm_farm: scripts/darc-slurm on a real single-node Slurm cluster on localhost.

The test starts its own munged, slurmctld and slurmd (Debian's slurm-wlm and munge, installed by
`scripts/setup --slurm`), configured in a scratch folder with ports of their own, so it touches no
Slurm or munge the machine may already run. It then renders a 12-frame sequence as 4 array tasks
of 3 frames, cancels one task while darc renders its first frame (scancel JOB_TASK), checks the
status command's done / missing lists, submits the same command again, and checks that every frame
exists, opens and is the image of a local darc render of the same frames: bitwise the same pixels,
windows, channels and attributes but the render time and date (farm_images.py). Then it renders three
frames cut into 4 tiles each (--tiles 4, 12 array tasks at once), merged by the last tile of
each frame, and checks them against the same local render. The daemons are stopped at the end
whatever happens (and die with this process if it is killed: PR_SET_PDEATHSIG).

Exit codes: 0 passed, 1 failed, 77 skipped (ctest SKIP_RETURN_CODE): Slurm or munge is not
installed, or the test does not run as root. Under CI (CI=true) those fail instead of skipping.

    tests/farm/slurm_farm_test.py --darc build/darc --darc-slurm scripts/darc-slurm --scratch DIR
"""

from __future__ import annotations

import argparse
import ctypes
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from farm_images import same_image  # noqa: E402
from farm_scene import write_sequence_rib  # noqa: E402

EXIT_SKIP = 77
FRAMES = 12
CHUNK = 3  # frames per array task: 4 tasks
CANCELLED_TASK = 1  # frames 4-6; frame 4 is the scene's slow frame, rendering when scancel comes
# The tiled farm: frames 1-3 (not the slow one), 4 rows each.
TILED_FRAMES = 3
TILES = 4
# How long to wait for each thing the daemons or jobs should do before the test fails: far above
# what each takes here (seconds), so that only a hang ends the test.
DAEMON_START_SECONDS = 60
RENDER_WAIT_SECONDS = 240
POLL_SECONDS = 0.2
# Unix socket paths are limited to 108 bytes; munged's socket lives elsewhere if the scratch
# folder's path is longer than this.
MAX_SOCKET_PATH = 100
REQUIRED_COMMANDS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel", "scontrol")
PR_SET_PDEATHSIG = 1


class TestFailure(Exception):
    pass


def check(condition: bool, message: str) -> None:
    if not condition:
        raise TestFailure(message)


def log(message: str) -> None:
    print(f"slurm_farm: {message}", flush=True)


def skip_or_fail(reason: str) -> int:
    if os.environ.get("CI"):
        print(f"slurm_farm: FAILED: {reason} (CI must run this test: .ci/run calls scripts/setup --slurm)",
              file=sys.stderr)
        return 1
    print(f"slurm_farm: SKIPPED: {reason}", file=sys.stderr)
    return EXIT_SKIP


def free_ports(count: int) -> list[int]:
    """Ports nobody listens on now (the kernel's choice); a small race with other programs is
    possible but harmless: the daemon then fails to bind and the test says so."""
    sockets = []
    try:
        for _ in range(count):
            s = socket.socket()
            s.bind(("127.0.0.1", 0))
            sockets.append(s)
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def die_with_parent() -> None:
    """In the daemon's process before exec: SIGTERM when the test process dies, however it dies."""
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def stop_leftovers(scratch: Path) -> None:
    """Kills what an earlier run of this test left behind when it was killed itself (SIGKILL
    cannot be caught): its daemons die with it (die_with_parent), but slurmstepd processes of its
    jobs outlive them, holding files of the scratch folder open. Only processes with a file open
    in this test's scratch folder are touched."""
    inside = str(scratch) + os.sep
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit() or int(proc.name) == os.getpid():
            continue
        try:
            holds = any(os.readlink(fd).startswith(inside) for fd in (proc / "fd").iterdir())
        except OSError:  # gone, or not ours to look at
            continue
        if holds:
            try:
                os.kill(int(proc.name), signal.SIGKILL)  # slurmstepd ignores SIGTERM without its slurmd
                log(f"killed process {proc.name}, left over from an earlier run")
            except ProcessLookupError:
                pass


def wait_for(what: str, condition, seconds: float, on_timeout=None):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(POLL_SECONDS)
    details = on_timeout() if on_timeout else ""
    raise TestFailure(f"timed out after {seconds:.0f} s waiting for {what}{details}")


class SlurmCluster:
    """munged + slurmctld + slurmd on 127.0.0.1, everything in `root` (and a short socket folder)."""

    def __init__(self, root: Path):
        self.root = root
        self.processes: list[tuple[str, subprocess.Popen]] = []
        self.node = socket.gethostname().split(".")[0]
        short = root / "run"
        if len(str(short / "munge.socket")) > MAX_SOCKET_PATH:
            short = Path(tempfile.mkdtemp(prefix="darc-slurm-"))
        self.run = short
        self.conf = root / "slurm.conf"
        self.env = dict(os.environ, SLURM_CONF=str(self.conf))

    def _start(self, name: str, command: list[str]) -> None:
        out = open(self.root / "log" / f"{name}.out", "w")
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   env=self.env, preexec_fn=die_with_parent)
        self.processes.append((name, process))

    def _log_tails(self) -> str:
        text = ""
        for name in ("munged.out", "slurmctld.log", "slurmd.log", "slurmctld.out", "slurmd.out"):
            path = self.root / "log" / name
            if path.exists():
                lines = path.read_text(errors="replace").splitlines()[-15:]
                text += f"\n--- {path} (last lines)\n" + "\n".join(lines)
        return text

    def _check_alive(self) -> None:
        for name, p in self.processes:
            if p.poll() is not None:
                raise TestFailure(f"{name} exited with {p.returncode}{self._log_tails()}")

    def start(self) -> None:
        for sub in ("munge", "state", "spool", "log"):
            (self.root / sub).mkdir(parents=True)
        self.run.mkdir(exist_ok=True)
        # munged refuses keys and folders that others can read or write.
        os.chmod(self.root / "munge", 0o700)
        os.chmod(self.run, 0o755)
        key = self.root / "munge" / "munge.key"
        key.write_bytes(os.urandom(128))  # what mungekey --create makes (1024 bits)
        os.chmod(key, 0o400)
        socket_path = self.run / "munge.socket"
        self._start("munged", ["munged", "--foreground", f"--key-file={key}", f"--socket={socket_path}",
                               f"--pid-file={self.run / 'munged.pid'}", f"--log-file={self.root / 'log' / 'munged.log'}",
                               f"--seed-file={self.root / 'munge' / 'munged.seed'}"])
        wait_for("munged's socket", lambda: (self._check_alive(), socket_path.exists())[1], DAEMON_START_SECONDS,
                 self._log_tails)

        ctld_port, slurmd_port = free_ports(2)
        cpus = os.cpu_count() or 1
        self.conf.write_text(f"""\
# Written by tests/farm/slurm_farm_test.py: a one-node cluster on localhost, for one test run.
ClusterName=darcfarmtest
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
AuthType=auth/munge
AuthInfo=socket={socket_path}
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation={self.root / 'state'}
SlurmdSpoolDir={self.root / 'spool'}
SlurmctldPidFile={self.run / 'slurmctld.pid'}
SlurmdPidFile={self.run / 'slurmd.pid'}
SlurmctldLogFile={self.root / 'log' / 'slurmctld.log'}
SlurmdLogFile={self.root / 'log' / 'slurmd.log'}
# No cgroups (a container may have none to give): processes tracked by parent id, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
# Seconds between SIGTERM and SIGKILL when a task is cancelled (default 30).
KillWait=5
MailProg=/bin/true
# RealMemory well below any machine's, so that --mem requests up to it are accepted.
NodeName={self.node} NodeAddr=127.0.0.1 CPUs={cpus} RealMemory=1000 State=UNKNOWN
PartitionName=darctest Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
""")
        self._start("slurmctld", ["slurmctld", "-D", "-f", str(self.conf)])
        self._start("slurmd", ["slurmd", "-D", "-f", str(self.conf), "-N", self.node])

        def node_idle() -> bool:
            self._check_alive()
            r = subprocess.run(["sinfo", "--noheader", "--format=%T", f"--nodes={self.node}"], env=self.env,
                               capture_output=True, text=True)
            return r.returncode == 0 and r.stdout.strip() == "idle"
        wait_for("the node to be idle (sinfo)", node_idle, DAEMON_START_SECONDS, self._log_tails)

    def stop(self) -> None:
        if any(name == "slurmctld" and p.poll() is None for name, p in self.processes):
            subprocess.run(["scancel", "--user=root"], env=self.env, capture_output=True, timeout=30)
        for name, p in reversed(self.processes):
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
        if self.run != self.root / "run":
            shutil.rmtree(self.run, ignore_errors=True)


def run(command: list[str], env: dict, expect: int | None = 0) -> subprocess.CompletedProcess:
    r = subprocess.run(command, env=env, capture_output=True, text=True, timeout=RENDER_WAIT_SECONDS)
    if expect is not None and r.returncode != expect:
        raise TestFailure(f"{' '.join(command)}: exit {r.returncode}, expected {expect}\n"
                          f"stdout:\n{r.stdout}\nstderr:\n{r.stderr}")
    return r


def farm_status(darc_slurm: str, farm: Path, env: dict) -> dict:
    r = run([darc_slurm, "status", "--dir", str(farm), "--json"], env, expect=None)
    check(r.returncode in (0, 1), f"darc-slurm status: exit {r.returncode}\n{r.stderr}")
    return json.loads(r.stdout)


def farm_test(args, scratch: Path, cluster: SlurmCluster) -> None:
    env = cluster.env
    rib = scratch / "sequence.rib"
    write_sequence_rib(rib, FRAMES, slow_frame=CANCELLED_TASK * CHUNK + 1)
    log("rendering the reference frames locally")
    (scratch / "local").mkdir()
    run([args.darc, "--quiet", "--frames", f"1-{FRAMES}", "-o", str(scratch / "local" / "f.####.exr"), str(rib)], env)

    farm = scratch / "farm"
    submit = [args.darc_slurm, "submit", "--dir", str(farm), "--frames", f"1-{FRAMES}", "--chunk", str(CHUNK),
              "--partition", "darctest", "--time", "10", "--mem", "200M", "--cpus-per-task", "1",
              "--darc", args.darc, "-o", str(scratch / "out" / "f.####.exr"), str(rib)]
    r = run(submit, env)
    match = re.search(r"submitted job (\d+): 4 array tasks", r.stdout)
    check(match is not None, f"first submission: expected 4 array tasks:\n{r.stdout}")
    job = match.group(1)
    log(f"submitted job {job}")

    # The Slurm options reached the job (scontrol shows each array task, with the job's options).
    shown = run(["scontrol", "show", "job", job], env).stdout
    for expected in ("Partition=darctest", "TimeLimit=00:10:00", "MinMemoryNode=200M", "CPUs/Task=1"):
        check(expected in shown, f"scontrol show job {job}: no {expected}:\n{shown}")

    # Cancel task 1 while darc renders its first frame (the slow one): darc has reported progress
    # in the frame's log (a line per 10 %, "f.0004.exr: 20% (...)") and the attempt has not ended.
    slow_log = farm / "logs" / f"frame.{CANCELLED_TASK * CHUNK + 1:04d}.log"

    def rendering() -> bool:
        text = slow_log.read_text() if slow_log.exists() else ""
        return re.search(r"\.exr: \d+% ", text) is not None and "darc-slurm: exit" not in text
    wait_for(f"{slow_log} to show darc rendering", rendering, RENDER_WAIT_SECONDS)
    run(["scancel", f"{job}_{CANCELLED_TASK}"], env)
    log(f"cancelled task {job}_{CANCELLED_TASK}")

    status = wait_for("job to leave the queue",
                      lambda: (lambda s: s if not any(j["active"] for j in s["jobs"]) else None)(
                          farm_status(args.darc_slurm, farm, env)), RENDER_WAIT_SECONDS)
    cancelled = list(range(CANCELLED_TASK * CHUNK + 1, (CANCELLED_TASK + 1) * CHUNK + 1))
    missing = [m["frame"] for m in status["missing"]]
    check(status["failed"] == [], f"no frame failed: {status['failed']}")
    # The cancelled task loses the frame it was rendering and those after it in its chunk (frame 4
    # takes seconds, so the cancel lands in it; a slower machine could land it in frame 5).
    check(bool(missing) and missing[0] in cancelled and missing == cancelled[cancelled.index(missing[0]):],
          f"missing frames {missing}: expected the cancelled task's frames {cancelled}, from the one it was "
          "rendering on")
    check("interrupted by SIGTERM" in status["missing"][0]["reason"],
          f"frame {missing[0]}: {status['missing'][0]['reason']}; expected it interrupted while rendering")
    check(status["done"] == [f for f in range(1, FRAMES + 1) if f not in missing], f"done: {status['done']}")
    for f in missing:
        check(not (scratch / "out" / f"f.{f:04d}.exr").exists(), f"frame {f} was cancelled, but its image exists")
    log(f"after the cancel: done {len(status['done'])}, missing {missing} ({status['missing'][0]['reason']})")

    # The same command again, with --wait (it returns when the job has left the queue, printing the
    # status; exit 0: every frame done): only the missing frames are submitted.
    r = run(submit + ["--wait"], env, expect=None)
    again = re.search(r"submitted job (\d+): (\d+) array tasks of up to 3 frames, frames (\S+) \(", r.stdout)
    check(r.returncode == 0 and again is not None and re.search(r"^done +12  1-12$", r.stdout, re.M) is not None,
          f"second submission (--wait): exit {r.returncode}\n{r.stdout}\n{r.stderr}")
    check(again.group(3) == (f"{missing[0]}-{missing[-1]}" if len(missing) > 1 else str(missing[0])),
          f"second submission: frames {again.group(3)}, expected the missing {missing}")
    log(f"resubmitted as job {again.group(1)} (frames {again.group(3)}) and waited:\n" + r.stdout.rstrip())
    final = farm_status(args.darc_slurm, farm, env)
    check(final["done"] == list(range(1, FRAMES + 1)) and not any(j["active"] for j in final["jobs"]),
          f"status after the second job: {final}")

    # Every frame: exists, opens, pixels bitwise those of the local render; a log that ends with
    # exit 0, and its own stats.
    for f in range(1, FRAMES + 1):
        difference = same_image(scratch / "out" / f"f.{f:04d}.exr", scratch / "local" / f"f.{f:04d}.exr")
        check(difference == "", f"frame {f}: {difference}")
        frame_log = (farm / "logs" / f"frame.{f:04d}.log").read_text()
        check(frame_log.rstrip().endswith("darc-slurm: exit 0"), f"frame {f}'s log:\n{frame_log}")
        check("'--threads' '1'" in frame_log, f"frame {f}: darc did not get --threads 1 from --cpus-per-task 1")
        stats = json.loads((farm / "stats" / f"frame.{f:04d}.json").read_text())
        check([e["frame"] for e in stats["frames"]] == [f], f"frame {f}'s stats: {stats['frames']}")
    leftovers = [p.name for p in (scratch / "out").iterdir() if not re.fullmatch(r"f\.\d{4}\.exr", p.name)]
    # The interrupted frame's log keeps both attempts: the cancelled one, then the one that finished.
    attempts = (farm / "logs" / f"frame.{missing[0]:04d}.log").read_text()
    check(attempts.count("darc-slurm: frame ") == 2 and attempts.index("interrupted by SIGTERM") <
          attempts.index("darc-slurm: exit 0"), f"frame {missing[0]}'s log:\n{attempts}")
    log(f"all {FRAMES} frames match the local render" +
        (f" (temporary files of the cancelled write: {leftovers})" if leftovers else ""))

    # Once everything is done, the same command submits nothing.
    r = run(submit, env)
    check("nothing to submit: 12 of 12 frames done" in r.stdout, f"third submission:\n{r.stdout}")


def tiled_farm_test(args, scratch: Path, cluster: SlurmCluster) -> None:
    """Frames 1-3 of the sequence, each cut into 4 rows (--tiles 4): 12 array tasks on the node's
    CPUs at once, the last tile of each frame merging it; every frame bitwise the local render."""
    env = cluster.env
    farm = scratch / "farm-tiled"
    out = scratch / "out-tiled"
    r = run([args.darc_slurm, "submit", "--dir", str(farm), "--frames", f"1-{TILED_FRAMES}", "--tiles", str(TILES),
             "--partition", "darctest", "--time", "10", "--cpus-per-task", "1", "--darc", args.darc,
             "-o", str(out / "f.####.exr"), "--wait", str(scratch / "sequence.rib")], env, expect=None)
    check(r.returncode == 0 and f"{TILED_FRAMES * TILES} array tasks of up to 1 tile of {TILES} per frame" in r.stdout
          and re.search(rf"^done +{TILED_FRAMES}  1-{TILED_FRAMES}$", r.stdout, re.M) is not None,
          f"tiled submission (--wait): exit {r.returncode}\n{r.stdout}\n{r.stderr}")
    log("tiled frames:\n" + r.stdout.rstrip())
    for f in range(1, TILED_FRAMES + 1):
        difference = same_image(out / f"f.{f:04d}.exr", scratch / "local" / f"f.{f:04d}.exr")
        check(difference == "", f"tiled frame {f}: {difference}")
        merges = (farm / "logs" / f"frame.{f:04d}.log").read_text()
        check(merges.count(f"merged {TILES} tiles into") == 1, f"frame {f} was not merged exactly once:\n{merges}")
    check(sorted(p.name for p in out.iterdir()) == [f"f.{f:04d}.exr" for f in range(1, TILED_FRAMES + 1)],
          f"the tiled output folder: {sorted(p.name for p in out.iterdir())}")
    check(not list((farm / "tiles").glob("*.exr")), f"tiles left: {list((farm / 'tiles').glob('*.exr'))}")
    log(f"all {TILED_FRAMES} tiled frames match the local render")


def main() -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--darc", required=True)
    p.add_argument("--darc-slurm", required=True)
    p.add_argument("--scratch", required=True, type=Path)
    args = p.parse_args()
    args.darc, args.darc_slurm = os.path.abspath(args.darc), os.path.abspath(args.darc_slurm)
    missing = [c for c in REQUIRED_COMMANDS if shutil.which(c) is None]
    if missing:
        return skip_or_fail(f"{', '.join(missing)} not installed (scripts/setup --slurm installs Slurm and munge)")
    if os.geteuid() != 0:
        return skip_or_fail("slurmd must run as root to start jobs, and this test does not run as root")
    try:
        import OpenImageIO  # noqa: F401
    except ImportError:
        return skip_or_fail("python3-openimageio is not installed (scripts/setup installs it)")

    scratch = args.scratch.resolve()
    stop_leftovers(scratch)
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    cluster = SlurmCluster(scratch / "slurm")
    # ctest stops a test that runs past its timeout with SIGTERM (then SIGKILL): stop the daemons.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("slurm_farm: stopped by SIGTERM"))
    try:
        log(f"starting munged, slurmctld and slurmd in {cluster.root}")
        cluster.start()
        farm_test(args, scratch, cluster)
        tiled_farm_test(args, scratch, cluster)
    except TestFailure as e:
        print(f"slurm_farm: FAILED: {e}", file=sys.stderr)
        return 1
    finally:
        cluster.stop()
    log("passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
