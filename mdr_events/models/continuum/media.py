r"""What the continuum's springs are made of: the half-space, or a layer of finite thickness on a rigid base.

On the half-space every spring has ``E*`` and ``G*`` per length: the spans integrate ``F_x = 2G* ∫₀ᵃ u dξ`` with the
slip zones' lengths, the cap (13) is ``ū = K a`` and the branches are (9). On a layer the springs' stiffness varies
with ``ξ`` (:mod:`mdr_events.theory.layer_continuum_symbolic` re-derives each of those assumptions): a span weighs a
zone ``[ξ₁, ξ₂]`` by ``M(ξ₂) − M(ξ₁)``, ``M(ξ) = K_t(ξ)/(2G*) = ξ Φ_t(ξ/h)`` the springs' tangential measure, the
springs leaving the edge by ``w(a) = k_t(a)/G*``, the cap is ``ū = π a² τ0/K_t(a) = K a/Φ_t`` and the branches are the
layer's (:class:`~.layer_branch.LayerBranch`); the normal force is the layer's (10). Each kind is looked up once per
run (:func:`medium_of`):

===================================  ===================================================================================
kind                                 the springs
===================================  ===================================================================================
:class:`HalfSpaceMedium`             the paper's: lengths, ``K a``, the branches of the indenter's kind, as before
:class:`~.layer_media.LayerMedium`   a layer bonded to its base: the tables' ``Φ_t``, ``Θ``, ``γₙ`` (paraboloid,
                                     power law)
``FrictionlessLayerMedium``          a layer on a frictionless base: the normal springs of ``LayerMedium``, no
                                     tangential ones (``K_t = 0``: such a layer slides on its base; only paths without
                                     tangential motion run on it, ``F_x = 0``)
===================================  ===================================================================================

On a layer the spans take the friction law ``"tau0"`` alone and the paper's adhesion law (:func:`check_law`); Coulomb's
part runs there spring by spring (:mod:`.play_run`), with or without adhesion.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from mdr_events.contact.friction import FrictionLaw
from mdr_events.contact.indenters import FlatPunch, Paraboloid, TabulatedProfile, indenter_kind
from mdr_events.contact.layer import HALF_SPACE, Layer
from mdr_events.memo import cached
from mdr_events.parameters import Parameters
from mdr_events.theory import power_law, symbolic, tabulated

if TYPE_CHECKING:
    from .anchors import AnchorMap, Piece

__all__ = ["HalfSpaceMedium", "HALF_SPACE_MEDIUM", "medium_of", "check_law", "layer_medium",
           "FACTOR_CACHE"]


#: How many radii's tangential factors a layer's medium remembers (``LayerMedium._factor``, :mod:`.layer_media`).
FACTOR_CACHE = 256


class HalfSpaceMedium:
    """The half-space: every spring alike (``G*`` per length), the cap ``K a`` (13), the paper's branches (9)."""

    #: whether the cap ``ū(a)`` is linear in the radius (``K a``): with a convex branch, the closed-form span's
    #: levels against a fixed target are convex in time and their rates monotone (:mod:`.closed_form`); ``False``
    #: for every subclass unless its own body sets it (:meth:`__init_subclass__`)
    linear_cap = True

    def __init_subclass__(cls, **kwargs):
        """A subclass's :attr:`linear_cap` is ``False`` unless its own body declares it (fails closed: a new medium
        never inherits the half-space's proof, so its events stay under the closed form's hidden-turn guard)."""
        super().__init_subclass__(**kwargs)
        cls.linear_cap = bool(cls.__dict__.get("linear_cap", False))

    def shift(self, K: float, a: float) -> float:
        """The cap of ``τ0``'s part at radius ``a``: ``K a`` (13).

        Parameters
        ----------
        K : float
            The half-space's cap per radius (m/m).
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``ū`` (m).
        """
        return K * a

    def span_primitive(self, integrator):
        """A moving span's force in closed form (:func:`~.closed_form.span_primitive`).

        Parameters
        ----------
        integrator : SpanIntegrator
            A moving span without a front.

        Returns
        -------
        Primitive
            ``P``.
        """
        from .closed_form import span_primitive

        return span_primitive(integrator)

    def shift_slope(self, K: float, a: float) -> float:
        """``dū/da``: ``K``.

        Parameters
        ----------
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            ``dū/da`` (1).
        """
        return K

    def measure(self, lower: float, upper: float) -> float:
        """The springs' tangential measure of ``[lower, upper]`` in units of ``G*``: its length.

        Parameters
        ----------
        lower, upper : float
            The interval's ends (m).

        Returns
        -------
        float
            ``upper − lower`` (m).
        """
        return upper - lower

    def density(self, x: float) -> float:
        """The springs' tangential stiffness at ``x`` in units of ``G*``: 1.

        Parameters
        ----------
        x : float
            The coordinate (m).

        Returns
        -------
        float
            1.
        """
        return 1.0

    def piece_integral(self, anchors: "AnchorMap", piece: "Piece", lower: float, upper: float) -> float:
        """``∫ w Y dξ`` over ``[lower, upper]`` of ``piece`` (``w = 1``: :meth:`~.anchors.AnchorMap.integral`).

        Parameters
        ----------
        anchors : AnchorMap
            The map holding ``piece``.
        piece : Piece
            The piece.
        lower, upper : float
            The bounds (m).

        Returns
        -------
        float
            The integral (m²).
        """
        return anchors.integral(piece, lower, upper)

    def full_slip_force(self, G_star: float, K: float, a: float) -> float:
        """``|F_x|`` with every spring at one cap of ``τ0``: ``2G* K a² = π a² τ0``.

        Parameters
        ----------
        G_star : float
            ``G*`` (Pa).
        K : float
            The half-space's cap per radius.
        a : float
            The contact radius (m).

        Returns
        -------
        float
            The force (N).
        """
        return 2.0 * G_star * K * a**2

    def edge(self, adhesion, params: Parameters, profile):
        """The branches of the contact's edge (:func:`~.edges.edge_of`).

        Parameters
        ----------
        adhesion : Adhesion
            The adhesion law.
        params : Parameters
            The material and the works.
        profile : PowerLaw, FlatPunch, TabulatedProfile or None
            The indenter (``None``: the paraboloid of ``params.R``).

        Returns
        -------
        Edge
            The growing and shrinking branches.
        """
        from .edges import edge_of

        return edge_of(adhesion, params, profile)

    def normal_force(self, params: Parameters, profile, depth, radius):
        r"""``F_N`` (10) of the springs in ``|x| < a`` at depth ``d``, vectorised (the flat punch's ``2 E* a d``).

        .. math:: F_N = 2 E^* \int_0^a \left(d - g(x)\right) \mathrm{d}x \qquad (10)

        Parameters
        ----------
        params : Parameters
            The material and ``R``.
        profile : PowerLaw, FlatPunch, TabulatedProfile or None
            The indenter.
        depth, radius : float or array_like
            ``d`` and ``a`` (m).

        Returns
        -------
        float or numpy.ndarray
            ``F_N`` (N).
        """
        return _HALF_SPACE_FORCES.get(indenter_kind(profile), _power_law_force)(params, profile, depth, radius)


def _paraboloid_force(params: Parameters, profile, depth, radius):
    from mdr_events.theory import analytic

    return analytic.normal_force(depth, radius, params)


def _flat_punch_force(params: Parameters, profile, depth, radius):
    return symbolic.relation("flat_punch_normal_force").numeric(depth, radius, params.E_star)


def _tabulated_force(params: Parameters, profile, depth, radius):
    return tabulated._normal_force(depth, radius, profile, params)  # (unchecked: the run's own depths and radii)


def _power_law_force(params: Parameters, profile, depth, radius):
    return power_law._normal_force(depth, radius, power_law.check_profile(profile), params)  # (unchecked, as above)


#: The half-space's normal force (10) of each kind of indenter, by its type (``None``: the paper's paraboloid; any
#: other: the power law's, whose relations name what they take).
_HALF_SPACE_FORCES = {type(None): _paraboloid_force, FlatPunch: _flat_punch_force, TabulatedProfile: _tabulated_force}


#: The half-space's medium (stateless: one for every run).
HALF_SPACE_MEDIUM = HalfSpaceMedium()




def check_law(friction: FrictionLaw, layer: Layer) -> None:
    """Refuse on a finite layer a friction law the continuum's spans do not run there: Coulomb's part (each spring's
    cap ``μ k/k_t (d − g)`` has a ratio of its own, no level is shared). ``simulate(..., method="continuum")`` and a
    continuum sweep run it spring by spring, with or without adhesion (:mod:`.play_run`,
    :mod:`mdr_events.analysis.play_sweep`); what reads the spans' solution itself (``solve_path``) refuses it.

    Parameters
    ----------
    friction : FrictionLaw
        The friction law.
    layer : Layer
        The layer.

    Raises
    ------
    ValueError
        A law with Coulomb's part on a layer of finite thickness.
    """
    if not layer.is_half_space and friction.coulomb_mu > 0.0:
        raise ValueError(f"friction={friction.law!r} is not allowed on {layer.describe()} in the continuum's spans (what "
                         "solve_path reads); allowed: 'tau0' (Coulomb's part runs on a layer spring by spring in "
                         "simulate(..., method='continuum') and a continuum sweep, and in method='discrete')")


def medium_of(params: Parameters, friction: FrictionLaw, profile, layer: Layer = HALF_SPACE) -> HalfSpaceMedium:
    """The continuum's medium of a run on ``layer`` (the one place the body's kind is looked up).

    Parameters
    ----------
    params : Parameters
        The material.
    friction : FrictionLaw
        The friction law (on a finite layer ``"tau0"`` alone, :func:`check_law`).
    profile : PowerLaw, FlatPunch, TabulatedProfile or None
        The indenter (on a finite layer the paraboloid, ``None``, a power law or the flat punch).
    layer : Layer, default the half-space
        The body.

    Returns
    -------
    HalfSpaceMedium, LayerMedium or FrictionlessLayerMedium
        The medium.

    Raises
    ------
    ValueError
        On a finite layer: another indenter or friction law.
    """
    if layer.is_half_space:
        return HALF_SPACE_MEDIUM
    check_law(friction, layer)
    return layer_medium(params, profile, layer)


def layer_medium(params: Parameters, profile, layer: Layer) -> HalfSpaceMedium:
    """The medium of a finite ``layer`` whatever the friction law (:func:`medium_of` checks the law first).

    Parameters
    ----------
    params : Parameters
        The material.
    profile : PowerLaw, FlatPunch or None
        The indenter (``None``: the paraboloid of ``params.R``).
    layer : Layer
        The layer (finite thickness).

    Returns
    -------
    LayerMedium or FrictionlessLayerMedium
        The medium.

    Raises
    ------
    ValueError
        Another indenter.
    """
    indenter = Paraboloid(params.R) if profile is None else profile
    return _layer_medium(params, indenter, layer)


@cached(16)  # (a user's unhashable indenter subclass by its exact value: issue 32 round 28 A3)
def _layer_medium(params: Parameters, indenter, layer: Layer) -> HalfSpaceMedium:
    from .layer_media import LAYER_MEDIA
    from .layer_normals import LAYER_NORMALS

    if indenter_kind(indenter) not in LAYER_NORMALS:
        raise ValueError(f"profile={indenter!r} is not allowed on {layer.describe()} in the continuum method; allowed: "
                         "the paraboloid, a PowerLaw or the FlatPunch (the layer's profile is tabulated for the first "
                         "two, the punch's is 0 under its face)")
    return LAYER_MEDIA[layer.base](params, indenter, layer)
