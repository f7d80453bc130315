"""The sliding length's batch over the spans (``span_sliding.span_sliding_lengths``) passes over a piece index that no
span's level reaches (round eight of issue 28): its values must stay those of each span's own
``AnchorMap.sliding_length`` bit for bit where a level sits exactly on a piece's lower value (the boundary of the
pass-over: ``>=``, not ``>``), where a level is ``nan``, and at random levels across every piece's range. The levels
are set exactly (a stand-in for the caps with no centre shift, so that the level is the position itself); the maps are
those of real runs (scenario A's two pieces, the zigzag's one to four). Zero tolerance: the same operations on the same
elements."""

from __future__ import annotations

import numpy as np
import pytest

from mdr_events.models.continuum.span_sliding import span_sliding_lengths, takes_batch

from test_evaluate_batch import _run


class _NoShift:
    """Caps of ``τ0``'s kind whose centre shift is 0: each cap's level is the indenter's position itself."""

    kappa = 0.0

    @staticmethod
    def centre_shift(radius, depth):
        return np.zeros(np.shape(radius))


def _levels(maps, radii, rng) -> list[np.ndarray]:
    """Per span: positions on every growth piece's lower and upper values exactly (as either cap reads them), a
    ``nan``, and random positions across the span's pieces' values."""
    found = []
    for m, a in zip(maps, radii):
        values = []
        for p in m.pieces:
            if not p.constant:
                ends = (m.piece_value(p, p.start), m.piece_value(p, min(p.end, float(np.max(a)))))
                values += [*ends, *(-v for v in ends)]
            else:
                values += [p.x0, -p.x0]
        values = np.array(values, dtype=float)
        spread = rng.uniform(np.min(values) - 1e-5, np.max(values) + 1e-5, size=len(a) - len(values) - 1)
        found.append(np.concatenate([values, [np.nan], spread])[:len(a)])
    return found


@pytest.mark.parametrize("case", ["A 20°", "zigzag", "reciprocating", "table, A 20°"])
def test_levels_on_the_pieces_values_are_each_spans_own(case):
    solution = _run(case)
    maps = [span.anchors for span in solution.spans if span.anchors is not None and takes_batch(span)]
    maps = [m for m in maps if m.attach is maps[0].attach and m.pieces]
    assert len(maps) > 1 and any(not p.constant for m in maps for p in m.pieces)
    rng = np.random.default_rng(28)
    samples = 40
    radii = [np.linspace(0.2, 1.0, samples) * max(p.end for p in m.pieces if np.isfinite(p.end)) for m in maps]
    depths = [np.full(samples, solution.params.d_max) for _ in maps]
    x = _levels(maps, radii, rng)
    caps = _NoShift()
    batch = span_sliding_lengths(caps, maps, np.concatenate(x), np.concatenate(depths), np.concatenate(radii),
                                 [samples] * len(maps))
    own = np.concatenate([m.sliding_length(caps, xs, ds, rs) for m, xs, ds, rs in zip(maps, x, depths, radii)])
    assert batch.tobytes() == own.tobytes()
