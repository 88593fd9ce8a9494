"""What an extraction found, as plain data (for --format json) and as lines of text."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from typing import Any

from .pipeline import Extraction


def report_data(extraction: Extraction) -> dict[str, Any]:
    """The extraction as JSON data: actors and their maneuvers, inferred conditions, replay."""
    fit = extraction.replay
    return {
        "recording": {
            "source": extraction.recording.source,
            "format": extraction.recording.format,
            "duration": round(extraction.recording.end - extraction.recording.start, 3),
        },
        "actors": [
            {
                "name": actor.name,
                "kind": actor.kind,
                "ego": actor.ego,
                "initial_speed": round(actor.initial_speed, 2),
                "maneuvers": [
                    {
                        "kind": event.kind,
                        "start": round(event.start, 2),
                        "end": round(event.end, 2),
                        "parameters": {
                            k: v for k, v in event.parameters.items() if not isinstance(v, tuple)
                        },
                        **(
                            {"destination": [round(v, 3) for v in event.destination]}
                            if event.destination
                            else {}
                        ),
                    }
                    for event in actor.maneuvers
                ],
            }
            for actor in extraction.actors
        ],
        "conditions": [
            {
                "node": item.node,
                "before": item.maneuver,
                "actor": item.actor,
                "start": round(item.start, 2),
                "kind": item.explanation.kind,
                "reference": item.explanation.actor,
                "target": item.explanation.target,
                "parameters": _plain(item.explanation.parameters),
                "fires": round(item.explanation.fires, 2),
                "confidence": item.explanation.confidence,
                "reason": item.explanation.reason,
                "alternatives": list(item.explanation.alternatives),
            }
            for item in extraction.inferred
        ],
        "replay": None
        if fit is None
        else {
            "compared_until": round(fit.until, 2),
            "ended": {"reason": fit.end_reason, "time": round(fit.replay_end, 2)},
            "largest_error": round(fit.largest, 3),
            "actors": [
                {
                    "name": a.name,
                    "largest_error": round(a.largest, 3),
                    "at": round(a.when, 2),
                    "mean_error": round(a.mean, 3),
                }
                for a in fit.actors
            ],
        },
        "thresholds": dataclasses.asdict(extraction.thresholds),
        "notes": list(extraction.notes),
    }


def _plain(parameters: dict[str, object]) -> dict[str, object]:
    return {
        key: [round(v, 3) for v in value] if isinstance(value, tuple) else value
        for key, value in parameters.items()
    }


def report_lines(extraction: Extraction) -> Iterator[str]:
    """The extraction in lines a reviewer reads: who did what when, why they started, the fit."""
    recording = extraction.recording
    yield f"{recording.source} ({recording.format}), {recording.end - recording.start:.2f} s"
    for actor in extraction.actors:
        ego = ", ego" if actor.ego else ""
        yield f"  {actor.name} ({actor.kind}{ego}), starting at {actor.initial_speed:.2f} m/s"
        for event in actor.maneuvers:
            values = ", ".join(
                f"{k}={v}" for k, v in event.parameters.items() if not isinstance(v, tuple)
            )
            yield f"    {event.start:6.2f}-{event.end:6.2f} s  {event.kind}({values})"
    if extraction.inferred:
        yield "  why each waiting maneuver started (condition before it):"
    for item in extraction.inferred:
        why = item.explanation
        yield (
            f"    {item.maneuver} of {item.actor} at {item.start:.2f} s: {item.node} = "
            f"{why.describe()}, fires at {why.fires:.2f} s; {why.confidence} ({why.reason})"
        )
        for other in why.alternatives:
            yield f"      also fits: {other}"
    fit = extraction.replay
    if fit is not None:
        yield (
            f"  replay in the preview: ended at {fit.replay_end:.2f} s by the {fit.end_reason}; "
            f"largest distance to the recording {fit.largest:.2f} m (until {fit.until:.2f} s)"
        )
        for a in fit.actors:
            yield f"    {a.name}: largest {a.largest:.2f} m at {a.when:.2f} s, mean {a.mean:.2f} m"
    for note in extraction.notes:
        yield f"  note: {note}"
