"""What the per-spring route's tests record of a run (imported by their modules in tests/models/), written once: the
springs each run makes (``play_run.PlaySprings`` patched to note every instance) and the readings its events' searches
ask (``play_run._readings`` patched to note each ask's kind)."""

from __future__ import annotations

from mdr_events.models.continuum import play_run
from mdr_events.models.continuum.play_springs import PlaySprings


def made_plays(monkeypatch) -> list[PlaySprings]:
    """The springs every run ``simulate`` starts after this call makes, in their order (``monkeypatch``, a pytest
    ``MonkeyPatch``, undoes the patch)."""
    made = []

    class Recorded(PlaySprings):
        def __post_init__(self) -> None:
            super().__post_init__()
            made.append(self)

    monkeypatch.setattr(play_run, "PlaySprings", Recorded)
    return made


def asked_readings(monkeypatch) -> list:
    """The kind (``play_run._Reading``) of every reading the events' searches ask after this call, in their order
    (``monkeypatch`` as :func:`made_plays`)."""
    asked = []
    readings = play_run._readings

    def recorded(play, asks):
        asked.extend(reading for reading, _ in asks)
        return readings(play, asks)

    monkeypatch.setattr(play_run, "_readings", recorded)
    return asked
