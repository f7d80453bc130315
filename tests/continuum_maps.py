"""Anchor maps the continuum's tests share."""

from __future__ import annotations

import mdr_events as me
from mdr_events.models.continuum import AnchorMap, Piece


def reversing_anchors(model, rtol: float) -> AnchorMap:
    """A jump-in plateau at x = 0, growth at dx/dd = 2 from the jump-in depth, then growth back at dx/dd = −3 (a
    reversal while growing): constant, rising and falling pieces, a map that is not monotone, on ``model``'s growing
    branch (radii to ``rtol``)."""
    branch = model.grow
    jump_in = me.analytic.jump_in_radius(model.params, model.params.dgamma0)
    rising = Piece(jump_in, 3e-3, 0.0, 2.0, branch.depth(jump_in))
    top = 2.0 * (branch.depth(3e-3) - branch.depth(jump_in))
    falling = Piece(3e-3, 4e-3, top, -3.0, branch.depth(3e-3))
    return AnchorMap(branch, rtol, [Piece(0.0, jump_in, 0.0), rising, falling])
