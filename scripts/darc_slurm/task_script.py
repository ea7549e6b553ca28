"""The batch script of one submission: array task i works through the items of chunk i, one darc
run per item, so that each item has its own log and exit code, and a task cancelled part-way loses
only the item it was on (darc writes an image under a temporary name and renames it when done).
An item is a frame (N), a tile of a frame cut with --tiles (N:K, tiles.py), or the merge of a
frame's rendered tiles (N:merge). After each tile, the task merges the frame's tiles if they are
all there (tile_merge.py says why the tasks merge, not a dependent job).

Each log keeps every attempt at its frame (tile). An attempt starts with "darc-slurm: frame N"
and ends with a line this tool reads back (frame_status.py):
    darc-slurm: exit N                   darc (the merge) ended with exit code N
    darc-slurm: interrupted by SIGTERM   the task was stopped (scancel, time limit, preemption)
An attempt without either line is still running, or its task was killed outright.

The script is plain bash and needs only darc, darc-slurm (for merges) and a file system shared
with the submitting machine. It also runs outside Slurm: SLURM_ARRAY_TASK_ID=0 bash DIR/tasks/submit-1.sh."""

from __future__ import annotations

import shlex

from darc_slurm.farm_folder import (LOG_PATTERN, STATS_PATTERN, TILE_IMAGE_STEM, TILE_LOG_STEM, TILE_STATS_STEM,
                                    FarmFolder, Sequence)
from darc_slurm.frames import split_frame_pattern
from darc_slurm.tiles import frame_tiles

LOG_ATTEMPT_PREFIX = "darc-slurm: frame "
LOG_EXIT_PREFIX = "darc-slurm: exit "
LOG_INTERRUPTED_PREFIX = "darc-slurm: interrupted by "

_HEADER = """\
#!/bin/bash
# Submission {number} of the darc-slurm farm folder {folder}, written by scripts/darc-slurm.
# Array task i works through the items of chunks[i]: a frame N (one darc run: the image goes to
# {output}, darc writes it atomically; the log to logs/frame.NNNN.log, each attempt appended,
# ending with "darc-slurm: exit N" or "darc-slurm: interrupted by SIGTERM"; the stats to
# stats/frame.NNNN.json), a tile N:K (the same into tiles/, logs/ and stats/frame.NNNN.tile.K.*,
# then the frame's tiles merged if they are all there), or N:merge (only the merge, logged in the
# frame's log). Outside Slurm: SLURM_ARRAY_TASK_ID=0 bash {script}
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
child_pid=""
# scancel, a time limit or preemption send SIGTERM to the task: stop darc or the merge (Slurm
# signals them too), say so in the log, and end the task. Nothing half-written is left as an
# image: darc and the merge rename their temporary file only once the image is complete.
stop() {
  if [ -n "$child_pid" ]; then kill -TERM "$child_pid" 2>/dev/null; fi
  if [ -n "$current_log" ]; then echo "darc-slurm: interrupted by SIG$1" >> "$current_log"; fi
  exit $((128 + $2))
}
trap 'stop TERM 15' TERM
trap 'stop INT 2' INT

# One attempt, appended to log $1: what $2 names, the command (the other arguments), its output
# and its exit code.
attempt() {
  local log=$1 what=$2 rc
  shift 2
  current_log=$log
  {
    echo "darc-slurm: $what, task ${SLURM_ARRAY_JOB_ID:-local}_${SLURM_ARRAY_TASK_ID}, host $(hostname), $(date '+%Y-%m-%d %H:%M:%S %z')"
    echo "darc-slurm: command: ${*@Q}"
  } >> "$log"
  "$@" >> "$log" 2>&1 < /dev/null &
  child_pid=$!
  wait "$child_pid"
  rc=$?
  child_pid=""
  echo "darc-slurm: exit $rc" >> "$log"
  current_log=""
  return "$rc"
}

render_frame() {
  local frame=$1
  rib_files "$frame"
  attempt "$(log_file "$frame")" "frame $frame" "$darc" --frames "$frame" --skip-existing "${threads_args[@]}" \
    --stats "$stats" -o "$output" "${darc_args[@]}" "${ribs[@]}"
}

# Tile $2 (1 to tile_count) of frame $1: darc --crop renders its rows into tiles/.
render_tile() {
  local frame=$1 label=${tile_labels[$2 - 1]}
  local crop=(${tile_crops[$2 - 1]})
  rib_files "$frame"
  attempt "$(tile_log_stem "$frame").tile.$label.log" "frame $frame tile $2 of $tile_count" \
    "$darc" --frames "$frame" --skip-existing "${threads_args[@]}" --crop "${crop[@]}" \
    --stats "$tile_stem_stats.tile.$label.json" -o "$tile_stem_image.tile.$label.exr" "${darc_args[@]}" "${ribs[@]}"
}

merge_tiles() {
  attempt "$(log_file "$1")" "frame $1 merge" "$darc_slurm" merge --dir "$folder" --frame "$1"
}

task=${SLURM_ARRAY_TASK_ID:?"not a Slurm array task (set SLURM_ARRAY_TASK_ID to run one by hand)"}
if ! [[ "$task" =~ ^[0-9]+$ ]] || [ "$task" -ge "${#chunks[@]}" ]; then
  echo "darc-slurm: no array task $task in this submission (tasks 0 to $((${#chunks[@]} - 1)))" >&2
  exit 2
fi
status=0
for item in ${chunks[$task]}; do
  frame=${item%%:*}
  case "$item" in
    *:merge) merge_tiles "$frame" || status=$? ;;
    # darc's exit 3 may be another frame's scene error (frame_status.py): the merge decides by the tiles.
    *:*) render_tile "$frame" "${item#*:}" || status=$?
         merge_tiles "$frame" || status=$? ;;
    *) render_frame "$frame" || status=$? ;;
  esac
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


def task_script(folder: FarmFolder, sequence: Sequence, darc: str, darc_slurm: str, chunks: list[list[str]],
                number: int, script_name: str, user_sets_threads: bool) -> str:
    """The bash text of submission `number` (saved as `script_name` in the folder); `chunks`: each
    array task's items ("N", "N:K" or "N:merge")."""
    q = shlex.quote
    lines = [_HEADER.format(number=number, folder=folder.path, output=sequence.output,
                            script=folder.file(script_name))]
    lines.append(f"darc={q(darc)}")
    lines.append(f"darc_slurm={q(darc_slurm)}")
    lines.append(f"folder={q(str(folder.path))}")
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
    if sequence.tiles > 1:
        tiles = frame_tiles(sequence.tiles)
        lines.append(f"tile_count={sequence.tiles}  # rows per frame, top to bottom (tiles.py)")
        lines.append("tile_labels=(" + " ".join(t.label for t in tiles) + ")")
        lines.append("tile_crops=(" + " ".join(q(" ".join(t.crop())) for t in tiles) + ")  # darc --crop of each")
        lines.append(f"tile_stem_image={q(str(folder.file(TILE_IMAGE_STEM)))}  # darc fills in the frame number")
        lines.append(f"tile_stem_stats={q(str(folder.file(TILE_STATS_STEM)))}")
        lines.append("tile_log_stem() {  # the start of the names of frame $1's tile logs")
        lines.append("  printf '%s\\n' " + _frame_word(str(folder.file(TILE_LOG_STEM))))
        lines.append("}")
    lines.append("chunks=(")
    lines += [f'  "{" ".join(chunk)}"' for chunk in chunks]
    lines.append(")")
    return "\n".join(lines) + "\n" + _BODY
