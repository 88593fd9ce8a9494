"""From a recorded drive to a SceML scenario: maneuvers, their synchronisation, a replay check.

    >>> from sceml.extract import read_recording, extract
    >>> from sceml.maps import load_map
    >>> recording = read_recording("run.csv")                      # doctest: +SKIP
    >>> found = extract(recording, load_map("maps/intersection.xodr"),
    ...                 map_reference="../maps/intersection.xodr")  # doctest: +SKIP
    >>> found.scenario, found.inferred, found.replay.largest      # doctest: +SKIP

How it works, its thresholds and what it cannot tell: docs/extract.md.
"""

from __future__ import annotations

from .actors import ActorSpec, parse_actor
from .pipeline import ExtractedActor, Extraction, extract
from .readers import FORMATS, read_recording
from .recording import Recording, Track
from .thresholds import Thresholds

__all__ = [
    "FORMATS",
    "ActorSpec",
    "ExtractedActor",
    "Extraction",
    "Recording",
    "Thresholds",
    "Track",
    "extract",
    "parse_actor",
    "read_recording",
]
