"""darc's frame selections and frame-numbered names, with darc's own rules (app/frame_list.cpp),
so that the frames and files this tool expects are exactly the ones darc renders and writes."""

from __future__ import annotations

import re


class FrameListError(ValueError):
    """A --frames list darc would reject."""


def _parse_int(text: str) -> int:
    # std::from_chars takes an optional '-' but no '+' and no spaces.
    if not re.fullmatch(r"-?[0-9]+", text):
        raise ValueError(text)
    return int(text)


def parse_frame_list(text: str) -> list[int]:
    """The frames of a list like "1-10,15,20-40x5" (ranges inclusive, optional step), sorted and
    without repeats. Raises FrameListError with darc's wording for what darc rejects."""
    frames: set[int] = set()
    for item in text.split(","):
        step = 1
        frame_range = item
        if "x" in item:
            frame_range, _, step_text = item.partition("x")
            try:
                step = _parse_int(step_text)
            except ValueError:
                step = 0
            if step < 1:
                raise FrameListError(f'bad step in frame list item "{item}"')
        dash = frame_range.find("-", 1)  # a leading '-' would be a sign
        try:
            if dash < 0:
                first = last = _parse_int(frame_range)
            else:
                first, last = _parse_int(frame_range[:dash]), _parse_int(frame_range[dash + 1:])
        except ValueError:
            first, last = 1, 0
        if last < first:
            raise FrameListError(f'bad frame list item "{item}" (expected N, A-B or A-BxS)')
        frames.update(range(first, last + 1, step))
    return sorted(frames)


def format_frame_list(frames: list[int]) -> str:
    """The shortest darc list of sorted, distinct frames: runs of consecutive frames as A-B."""
    parts = []
    i = 0
    while i < len(frames):
        j = i
        while j + 1 < len(frames) and frames[j + 1] == frames[j] + 1:
            j += 1
        parts.append(str(frames[i]) if i == j else f"{frames[i]}-{frames[j]}")
        i = j + 1
    return ",".join(parts)


def _pad(frame: int, width: int) -> str:
    digits = str(abs(frame)).rjust(width, "0")
    return "-" + digits if frame < 0 else digits


def split_frame_pattern(name: str) -> tuple[str, int, str] | None:
    """(prefix, width, suffix) of the first frame pattern darc substitutes in `name` (a run of '#'
    gives its length; %d and %0Nd give N, 0 for %d), or None when the name has none."""
    hash_at = name.find("#")
    if hash_at >= 0:
        end = hash_at
        while end < len(name) and name[end] == "#":
            end += 1
        return name[:hash_at], end - hash_at, name[end:]
    percent = name.find("%")
    if percent >= 0:
        match = re.match(r"([0-9]*)d", name[percent + 1:])
        if match:
            width = int(match.group(1)) if match.group(1) else 0
            return name[:percent], width, name[percent + 1 + match.end():]
    return None


def has_frame_pattern(name: str) -> bool:
    return split_frame_pattern(name) is not None


def substitute_frame_number(name: str, frame: int) -> str:
    """`name` with the frame number in its pattern, as darc writes it (unchanged without one)."""
    parts = split_frame_pattern(name)
    if parts is None:
        return name
    prefix, width, suffix = parts
    return prefix + _pad(frame, width) + suffix


def chunks(frames: list[int], size: int) -> list[list[int]]:
    """`frames` in order, cut into pieces of `size` (the last may be shorter)."""
    return [frames[i:i + size] for i in range(0, len(frames), size)]
