"""Slurm's commands, as this tool uses them: sbatch to submit an array job, squeue to learn which
of a folder's jobs are still queued or running. Slurm finds its cluster as it always does
(slurm.conf, or $SLURM_CONF)."""

from __future__ import annotations

import dataclasses
import getpass
import shutil
import subprocess


class SlurmError(Exception):
    """A Slurm command that is missing or failed (exit code 1)."""


@dataclasses.dataclass(frozen=True)
class SbatchOptions:
    """The sbatch options darc-slurm passes through; None leaves Slurm's default."""

    partition: str | None = None
    time: str | None = None  # time limit per array task, in sbatch's forms (MM, HH:MM:SS, D-HH, ...)
    mem: str | None = None  # memory per node, e.g. 4G
    cpus_per_task: int | None = None  # also darc's --threads (the script reads SLURM_CPUS_PER_TASK)
    job_name: str | None = None
    max_running: int | None = None  # array tasks running at once (sbatch --array A-B%N)
    extra: tuple[str, ...] = ()  # any other sbatch arguments, as given


def _command(name: str) -> str:
    path = shutil.which(name)
    if path is None:
        raise SlurmError(f"{name} not found: is Slurm's client installed (Debian: slurm-client) and on PATH?")
    return path


def sbatch_command(script: str, tasks: int, slurm_output: str, workdir: str, options: SbatchOptions) -> list[str]:
    """The sbatch command line that submits `script` as the array job 0..tasks-1."""
    array = f"0-{tasks - 1}" + (f"%{options.max_running}" if options.max_running else "")
    command = ["sbatch", "--parsable", f"--array={array}", f"--output={slurm_output}", f"--chdir={workdir}"]
    for flag, value in (("--job-name", options.job_name), ("--partition", options.partition),
                        ("--time", options.time), ("--mem", options.mem),
                        ("--cpus-per-task", options.cpus_per_task)):
        if value is not None:
            command.append(f"{flag}={value}")
    return command + list(options.extra) + [script]


def submit(command: list[str]) -> str:
    """Runs an sbatch command line; returns the job id."""
    result = subprocess.run([_command(command[0])] + command[1:], capture_output=True, text=True)
    job_id = result.stdout.strip().split(";")[0]  # --parsable: "JOBID" or "JOBID;CLUSTER"
    if result.returncode != 0 or not job_id:
        raise SlurmError(f"sbatch failed (exit {result.returncode}): {result.stderr.strip() or result.stdout.strip()}")
    return job_id


def active_jobs(job_ids: list[str]) -> set[str]:
    """Which of these array jobs still have a task queued, running or completing."""
    if not job_ids:
        return set()
    # All of the user's jobs, filtered here: squeue --jobs fails on ids Slurm has already forgotten.
    result = subprocess.run([_command("squeue"), "--noheader", "--format=%F", f"--user={getpass.getuser()}"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise SlurmError(f"squeue failed (exit {result.returncode}): {result.stderr.strip()}")
    queued = {line.strip() for line in result.stdout.splitlines()}
    return {j for j in job_ids if j in queued}
