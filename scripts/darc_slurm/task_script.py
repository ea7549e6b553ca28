"""The batch script of one submission: array task i renders the frames of chunk i, one darc run per
frame, so that each frame has its own log and exit code, and a task cancelled part-way loses only
the frame it was rendering (darc writes an image under a temporary name and renames it when done).

A frame's log keeps every attempt at it. An attempt starts with "darc-slurm: frame N, task ..."
and ends with a line this tool reads back (frame_status.py):
    darc-slurm: exit N                   darc ended with exit code N
    darc-slurm: interrupted by SIGTERM   the task was stopped (scancel, time limit, preemption)
An attempt without either line is still rendering, or its task was killed outright.

The script is plain bash and needs only darc and a file system shared with the submitting machine.
It also runs outside Slurm: SLURM_ARRAY_TASK_ID=0 bash DIR/tasks/submit-1.sh."""

from __future__ import annotations

import shlex

from darc_slurm.farm_folder import LOG_PATTERN, STATS_PATTERN, FarmFolder, Sequence
from darc_slurm.frames import split_frame_pattern

LOG_ATTEMPT_PREFIX = "darc-slurm: frame "
LOG_EXIT_PREFIX = "darc-slurm: exit "
LOG_INTERRUPTED_PREFIX = "darc-slurm: interrupted by "

_HEADER = """\
#!/bin/bash
# Submission {number} of the darc-slurm farm folder {folder}, written by scripts/darc-slurm.
# Array task i renders the frames of chunks[i], one darc run per frame: the image goes to
# {output} (darc writes it atomically), the log to logs/frame.NNNN.log (each attempt appended,
# ending with "darc-slurm: exit N" or "darc-slurm: interrupted by SIGTERM"), the stats to
# stats/frame.NNNN.json. Outside Slurm: SLURM_ARRAY_TASK_ID=0 bash {script}
set -u
# The threads darc may use: the CPUs Slurm gave the task (--cpus-per-task, else what the node
# allocated to it), 1 outside Slurm.
threads=${{SLURM_CPUS_PER_TASK:-${{SLURM_CPUS_ON_NODE:-1}}}}
"""

_BODY = r"""
# darc's frame-number substitution (app/frame_list.cpp): PREFIX WIDTH SUFFIX FRAME.
frame_name() {
  local digits
  printf -v digits '%0*d' "$2" "${4#-}"
  if [ "${4:0:1}" = - ]; then digits="-$digits"; fi
  printf '%s%s%s' "$1" "$digits" "$3"
}

current_log=""
darc_pid=""
# scancel, a time limit or preemption send SIGTERM to the task: stop darc (Slurm signals it too),
# say so in the frame's log, and end the task. The frame's image is not written: darc renames its
# temporary file only once the image is complete.
stop() {
  if [ -n "$darc_pid" ]; then kill -TERM "$darc_pid" 2>/dev/null; fi
  if [ -n "$current_log" ]; then echo "darc-slurm: interrupted by SIG$1" >> "$current_log"; fi
  exit $((128 + $2))
}
trap 'stop TERM 15' TERM
trap 'stop INT 2' INT

render_frame() {
  local frame=$1 rc
  current_log=$(log_file "$frame")
  rib_files "$frame"
  local command=("$darc" --frames "$frame" --skip-existing "${threads_args[@]}"
                 --stats "$stats" -o "$output" "${darc_args[@]}" "${ribs[@]}")
  {
    echo "darc-slurm: frame $frame, task ${SLURM_ARRAY_JOB_ID:-local}_${SLURM_ARRAY_TASK_ID}, host $(hostname), $(date '+%Y-%m-%d %H:%M:%S %z')"
    echo "darc-slurm: command: ${command[*]@Q}"
  } >> "$current_log"
  "${command[@]}" >> "$current_log" 2>&1 < /dev/null &
  darc_pid=$!
  wait "$darc_pid"
  rc=$?
  darc_pid=""
  echo "darc-slurm: exit $rc" >> "$current_log"
  current_log=""
  return "$rc"
}

task=${SLURM_ARRAY_TASK_ID:?"not a Slurm array task (set SLURM_ARRAY_TASK_ID to run one by hand)"}
if ! [[ "$task" =~ ^[0-9]+$ ]] || [ "$task" -ge "${#chunks[@]}" ]; then
  echo "darc-slurm: no array task $task in this submission (tasks 0 to $((${#chunks[@]} - 1)))" >&2
  exit 2
fi
status=0
for frame in ${chunks[$task]}; do
  render_frame "$frame" || status=$?
done
exit "$status"
"""


def _frame_word(name: str) -> str:
    """A file name as a bash word for frame "$1": fixed, or with darc's pattern filled in."""
    parts = split_frame_pattern(name)
    if parts is None:
        return shlex.quote(name)
    prefix, width, suffix = parts
    return f'"$(frame_name {shlex.quote(prefix)} {width} {shlex.quote(suffix)} "$1")"'


def task_script(folder: FarmFolder, sequence: Sequence, darc: str, chunks: list[list[int]],
                number: int, script_name: str, user_sets_threads: bool) -> str:
    """The bash text of submission `number` (saved as `script_name` in the folder)."""
    q = shlex.quote
    lines = [_HEADER.format(number=number, folder=folder.path, output=sequence.output,
                            script=folder.file(script_name))]
    lines.append(f"darc={q(darc)}")
    lines.append(f"output={q(sequence.output)}")
    lines.append(f"stats={q(str(folder.file(STATS_PATTERN)))}  # darc fills in the frame number")
    lines.append("darc_args=(" + " ".join(q(a) for a in sequence.darc_args) + ")")
    # darc rejects an option given twice: the user's own --threads wins.
    lines.append("threads_args=()" if user_sets_threads else 'threads_args=(--threads "$threads")')
    lines.append("rib_files() {  # the RIB files of frame $1")
    lines.append("  ribs=(" + " ".join(_frame_word(r) for r in sequence.ribs) + ")")
    lines.append("}")
    lines.append("log_file() {  # the log of frame $1")
    lines.append("  printf '%s\\n' " + _frame_word(str(folder.file(LOG_PATTERN))))
    lines.append("}")
    lines.append("chunks=(")
    lines += [f'  "{" ".join(str(f) for f in chunk)}"' for chunk in chunks]
    lines.append(")")
    return "\n".join(lines) + "\n" + _BODY
