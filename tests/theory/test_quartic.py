"""The closed-form root of the branch's quartic (:mod:`mdr_events.theory.quartic`) against the iteration it replaces
at a run's samples (:meth:`~mdr_events.models.continuum.branch.Branch.radii`), sample by sample, to the root's own
conditioning: a few ulp where the root is simple, ``√ε`` of it at the jump-off fold."""

from __future__ import annotations

import numpy as np
import pytest

import mdr_events as me
from mdr_events.models.continuum.branch import Branch, PowerLawBranch
from mdr_events.contact.indenters import PowerLaw
from mdr_events.theory.quartic import depressed_quartic_root

EPS = np.finfo(float).eps
#: Horner's rounding of the degree-4 quartic, relative to the sum of its terms' magnitudes ``s⁴ + |P| s + |Q|``:
#: at most ``2n u = 4 ε`` (``n = 4`` multiply-adds, unit roundoff ``u = ε/2``; Higham, Accuracy and Stability, 5.1).
#: Each route's root moves by the root's response to that change of the polynomial (:func:`_root_shift`).
HORNER_ROUNDING = 4 * EPS
#: The iteration stops on a step of ``4 ε`` of the root (``positive_polynomial_root``'s ``rtol``); the square root
#: that turns the radii compared back into ``s`` rounds each by half an ulp: 5 ulp of ``s`` besides the conditioning.
STOP_AND_SQUARE_ROOT = 5 * EPS


def _root_shift(s: np.ndarray, linear: float, constant: np.ndarray) -> np.ndarray:
    """How far a root ``s`` of ``s⁴ + P s + Q`` moves when the polynomial changes by its rounding
    ``e = HORNER_ROUNDING (s⁴ + |P| s + |Q|)``: ``e / |p'(s)|`` where the root is simple, and at most
    ``√(2 e / p''(s))`` where ``p'`` vanishes (the fold: ``p' δ + p'' δ²/2 = e``)."""
    change = HORNER_ROUNDING * (s**4 + abs(linear) * s + np.abs(constant))
    slope = np.abs(4.0 * s**3 + linear)
    with np.errstate(divide="ignore"):
        simple = change / slope
    return np.minimum(simple, np.sqrt(2.0 * change / (12.0 * s**2)))


def _depths(branch: Branch, deepest: float) -> np.ndarray:
    """Depths from the fold (approached to ``1e-16`` of its depth) over zero to ``deepest``."""
    fold = branch.jump_off_depth
    return np.concatenate([fold * (1.0 - np.logspace(-16.0, -1.0, 200)), [fold, 0.0, 1e-300, -1e-300],
                           np.linspace(fold, deepest, 2001), np.geomspace(1e-12, deepest, 200)])


@pytest.mark.parametrize("radius", [30e-3, 100e-3])
@pytest.mark.parametrize("branch_work", ["dgamma0", "dgamma1"])
def test_the_closed_form_root_is_the_iterations_to_its_conditioning(radius, branch_work):
    params = me.Parameters.paper().replace(R=radius)
    branch = Branch(params, getattr(params, branch_work))
    depth = _depths(branch, 10 * params.d_max)
    iterated = branch.radii(depth)
    coefficients = branch._array_coefficients(depth, *branch._arguments)
    linear, constant = float(coefficients[3]), np.broadcast_to(coefficients[4], depth.shape)
    s_iterated = np.sqrt(iterated)
    # each route within the shift of its own root from the true one: the two within twice it
    allowed = 2.0 * _root_shift(s_iterated, linear, constant) + STOP_AND_SQUARE_ROOT * s_iterated
    # the closed form alone (the fold too), and the samples' radii (the iteration's own near the fold)
    for name, s_closed in [("closed form", depressed_quartic_root(linear, constant)),
                           ("sample_radii", np.sqrt(branch.sample_radii(depth)))]:
        assert np.all(np.isfinite(s_closed)), name
        excess = np.abs(s_closed - s_iterated) / allowed
        assert np.max(excess) <= 1.0, f"{name}, depth {depth[np.argmax(excess)]!r}: {np.max(excess):.3g} of the shift"


def test_the_samples_near_the_fold_are_the_iterations():
    """Where the quartic's slope is below NEAR_FOLD of its scale the samples take the iteration's radius, bit for bit
    (that of the events and extrema a run ending at pull-off reads there)."""
    params = me.Parameters.paper()
    branch = Branch(params, params.dgamma1)
    depth = branch.jump_off_depth * (1.0 - np.logspace(-16.0, -8.0, 50))
    np.testing.assert_array_equal(branch.sample_radii(depth), branch.radii(depth))


@pytest.mark.parametrize("branch_work", ["dgamma0", "dgamma1"])
def test_the_public_quartic_members_are_the_samples(branch_work):
    """What the closed-form pass of a run's radii reads off a branch (``sample_radii._quartic_radii``): the iteration's
    radius near the fold (:meth:`Branch.near_fold_radii`) is :meth:`Branch.sample_radii`'s there, bit for bit, each
    depth its own call (an iteration's last step depends on the elements it runs for); the quartic's linear
    coefficient (:attr:`Branch.quartic_linear`) is its NumPy form's; the root's floor (:attr:`Branch.root_floor`) is
    ``√a`` at the jump-off."""
    params = me.Parameters.paper()
    branch = Branch(params, getattr(params, branch_work))
    for depth in branch.jump_off_depth * (1.0 - np.logspace(-16.0, -8.0, 50)):
        one = np.array([depth])
        assert branch.near_fold_radii(one).tobytes() == branch.sample_radii(one).tobytes(), depth
    assert branch.quartic_linear == float(branch._quartic_of(np.array([0.0]))[3])
    assert branch.root_floor == np.sqrt(branch.jump_off_radius)


def test_below_the_fold_there_is_no_root_and_other_branches_iterate():
    params = me.Parameters.paper()
    branch = Branch(params, params.dgamma0)
    assert np.isnan(branch.sample_radii(np.array([1.5 * branch.jump_off_depth]))[0])
    hertz = Branch(params, 0.0)
    depth = np.linspace(0.0, params.d_max, 11)
    np.testing.assert_array_equal(hertz.sample_radii(depth), hertz.radii(depth))
    cone = PowerLawBranch(params, params.dgamma0, PowerLaw.cone(0.05))
    depth = np.linspace(cone.jump_off_depth, params.d_max, 11)
    np.testing.assert_array_equal(cone.sample_radii(depth), cone.radii(depth))


def test_every_other_indenter_s_samples_are_its_radii():
    """A table, the flat punch and a layer sample their branch by their own ``radii``, bit for bit (only the
    paraboloid's closed form differs from its iteration)."""
    from mdr_events.contact.indenters import FlatPunch, TabulatedProfile
    from mdr_events.models.continuum.branch import make_branch
    from mdr_events.models.continuum.media import medium_of
    params = me.Parameters.paper()
    r = np.linspace(0.0, 4e-3, 41)
    contact = me.Contact.paper().replace(h=5e-3)
    layered = contact.parameters(params.d_max, params.v)
    branches = [make_branch(params, params.dgamma0, TabulatedProfile(r, r**2 / (2 * params.R))),
                make_branch(params, params.dgamma0, FlatPunch(1e-3)),
                medium_of(layered, contact.friction, None, contact.layer).edge(contact.adhesion, layered, None).grow]
    for branch in branches:
        depth = np.linspace(branch.jump_off_depth, params.d_max, 11)
        np.testing.assert_array_equal(branch.sample_radii(depth), branch.radii(depth))


def test_a_new_branch_type_samples_by_its_own_radii_unless_it_declares_the_quartic():
    """``Branch.sample_radii`` fails closed: a subclass that does not declare :attr:`Branch.quartic_samples` (a new
    indenter's branch, here the paraboloid's equations under another name) samples by its own ``radii``, bit for bit;
    one that declares it gets the quartic, which differs from the iteration by rounding somewhere on the branch."""

    class Undeclared(Branch):
        pass

    class Declared(Branch):
        quartic_samples = True

    params = me.Parameters.paper()
    depth = np.linspace(Branch(params, params.dgamma0).jump_off_depth, params.d_max, 201)
    undeclared, declared = Undeclared(params, params.dgamma0), Declared(params, params.dgamma0)
    assert not Undeclared.quartic_samples and Declared.quartic_samples and Branch.quartic_samples
    np.testing.assert_array_equal(undeclared.sample_radii(depth), undeclared.radii(depth))
    np.testing.assert_array_equal(declared.sample_radii(depth), Branch(params, params.dgamma0).sample_radii(depth))
    assert np.any(declared.sample_radii(depth) != declared.radii(depth))
