r"""The generalized MDR for an elastic layer of thickness ``h`` on a rigid base (issue 34): the punch problem solved
numerically, tabulated against ``a/h``, and the MDR relations built on it.

The layer's punch problem
-------------------------
A rigid flat punch of radius ``a`` pressed by ``w₀`` into the layer (frictionless top; base bonded or frictionless,
:class:`~mdr_events.contact.layer.LayerBase`). In Hankel space the layer's surface displacement under a pressure
``p(r)`` is

.. math:: w(r) = \frac{2}{E^*}\int_0^\infty \hat p(\xi)\, C(\xi h)\, J_0(\xi r)\,\mathrm{d}\xi,
          \qquad \hat p(\xi) = \int_0^\infty p(r)\, r J_0(\xi r)\,\mathrm{d}r,

with the compliance function (:func:`compliance_function`; derived from Love's strain function in
:mod:`mdr_events.theory.layer_symbolic`, ``κ = 3 − 4ν``)

.. math:: C_\mathrm{bonded}(t) = \frac{2\kappa\sinh 2t - 4t}{2\kappa\cosh 2t + 1 + \kappa^2 + 4t^2}, \qquad
          C_\mathrm{frictionless}(t) = \frac{\cosh 2t - 1}{\sinh 2t + 2t},

``C → 1`` as ``t → ∞`` (the half-space). Writing ``p̂(ξ) = ∫₀ᵃ θ(t) cos ξt dt`` and inverting the Abel operator of
the contact condition ``w = w₀`` (``r < a``) gives the Fredholm equation of the second kind of Lebedev & Ufliand
(PMM 22 (1958) 442; the same kernels in Hayes, Keer, Herrmann & Mockros, J. Biomech. 5 (1972) 541), with
``θ(t) = (E* w₀/π) Θ(t/a)`` and ``λ = a/h``:

.. math:: \Theta(\tau) - \frac{\lambda}{\pi}\int_0^1 \Theta(\sigma)\,
          [k(\lambda(\tau-\sigma)) + k(\lambda(\tau+\sigma))]\,\mathrm{d}\sigma = 1,
          \qquad k(v) = \int_0^\infty [1 - C(u)] \cos(u v)\,\mathrm{d}u \quad (L1)

(:func:`kernel`). The force is ``F = 2π p̂(0)``: the stiffness ``K(a) = 2E* a Φ(λ)``, ``Φ = ∫₀¹ Θ`` (L2). The
edge value gives the slope: the punch's stress intensity ``K_I = θ(a) sqrt(π/a)`` and Griffith's balance (below)
make ``K'(a) = 2E* Θ(1)²`` (L3), so that ``d(λΦ)/dλ = Θ(1)²`` (checked by the tests). A profile ``f`` enters through
the right-hand side: at depth ``d``, ``θ = (E*/π)[d Θ − Θ_g]``, ``Θ_g`` the solution of (L1) with the right-hand side
``g∞(aτ)`` (``g∞`` the half-space's MDR profile, the Abel transform (3)); its non-adhesive depth, the generalized MDR
profile, is ``g(a) = Θ_g(1)/Θ(1)`` (L4) (no singular pressure at the edge). The surface outside the punch is
``φ(r; a) = (2/π)[arcsin(a/r) − ∫_a^r G(t/a)/sqrt(r² − t²) dt]`` with ``G = Θ − 1`` continued by (L1) (L5).

Numerics: Gauss–Legendre (Nyström) on ``[0, 1]`` with ``N = 40 + 6λ`` nodes (rounded up to 16; spectral: the kernel
is analytic in ``|Im v| < 2``); ``k`` from a Gauss–Legendre quadrature of ``1 − C`` (evaluated without
cancellation), kept as piecewise Chebyshev interpolants on ``v`` (20 points per unit). The solve converges to
round-off (1e-12 relative at ``λ = 20``) and the tables are interpolated to better than 1e-8.

The generalized MDR (Machines 11(4):474, 2023, doi:10.3390/machines11040474, and the works it cites)
----------------------------------------------------------------------------------------------------
The springs' stiffness density ``k(x) = K'(x)/2`` (:func:`spring_stiffness_density`), the equivalent profile from
``f(r) = ∫₀ʳ [1 − φ(r; ã)] g'(ã) dã`` (:func:`equivalent_profile`), the normal force
``F_N = ∫₋ₐᵃ k(x)(d − g(x)) dx = F₀(a) + K(a)(d − g(a))`` (:func:`normal_force`) and Heß's rule
``Δl = sqrt(4π a Δγ / K'(a))`` (:func:`hess_elongation`; from Griffith's balance, derived in
:mod:`mdr_events.theory.layer_symbolic`). At ``h = inf`` each is the half-space's relation exactly
(``Φ = Θ(1) = γ = 1``).

Tables
------
:func:`layer_table` tabulates, per ``(ν, base, n)``, ``Φ``, ``Θ(1)``, the profile factor ``γₙ = g/g∞`` and the force
factor ``χₙ = F₀/(2E* a g∞(a))`` of the power law ``c rⁿ`` against ``s = ln(a/h)`` from ``a/h = 1e-4`` to
:data:`LAMBDA_MAX` (quintic splines of the logarithms, error below 1e-8 against direct solves at the mid-points);
below ``1e-4`` the series ``Φ = Θ(1) = 1/(1 − 2k(0)λ/π)``, ``Θₙ(1) = 1 + (Φ − 1)/(n + 1)``, ``χₙ = n/(n + 1)``
(errors ``O(λ³)``). Built in about 2 s per ``(ν, base, n)`` and cached on disk (:func:`table_cache_path`).

Modules
-------
================================  ======================================================================================
module                            one idea
================================  ======================================================================================
:mod:`.compliance`                the compliance ``C(ξh)`` and the kernel ``k(v)`` of (L1), interpolated
:mod:`.punch`                     the Nyström solve of (L1) at one ``a/h``: :class:`PunchSolution`, ``φ`` (L5)
:mod:`.tables`                    the factors against ``a/h``, cached on disk: :class:`LayerTable`
:mod:`.table_store`               the tables on disk (normal and tangential): directory, key, grid, read or build
:mod:`.relations`                 the generalized MDR: ``K``, ``k(x)``, ``Δl``, ``g``, ``F_N``, the adhesive branch
:mod:`.force_control`             the pull-off under force control: :class:`PullOff`
:mod:`.branch_points`             the jump-off, the first touch and the pull-off force of a contact on its layer (what
                                  :func:`mdr_events.jump_off` and ``pull_off_force`` run on a layer)
:mod:`.checks`                    what the relations take and give, checked: arguments by name, finite results
:mod:`.branch_scan`               a branch scanned in ``ln a``: a depth inverted on its stable part, its least depth
:mod:`.branch_slopes`             the slopes of a branch's depth and force in ``ln a``; a flat least at its slope's root
:mod:`.curves`                    a :class:`~mdr_events.Contact` on its layer as labelled results: the branches against
                                  the depth, an indentation cycle, the pull-off against the thickness
:mod:`.tangential_compliance`     the tangential compliances ``C_L``, ``C_T`` and the kernels of the tangential punch
:mod:`.tangential_coupling`       the normal–tangential coupling the decoupled tangential punch neglects, its bound
:mod:`.tangential_punch`          the Nyström solve of the tangential punch at one ``a/h``
:mod:`.tangential_tables`         the tangential punch's factors against ``a/h``, cached on disk
:mod:`.tangential_displacement`   the surface displacement under the tangential punch by direct Hankel quadrature
:mod:`.tangential_relations`      the tangential springs ``k_t = K_t'/2`` and the caps
:mod:`.spring_factors`            a bonded layer's springs ``g``, ``k``, ``k_t`` at many ``x`` in one spline call
:mod:`.slip_onset`                the slip-onset depths (17)–(21) and the critical angles with the layer's cap and
                                  branches (what :func:`mdr_events.d_crit` and ``critical_angle`` run on a layer)
================================  ======================================================================================

The tangential modules' public names are those of :mod:`mdr_events.theory.layer_tangential` (not re-exported here).
"""

from mdr_events.theory.layer.branch_points import layer_jump_in_radius, layer_jump_off, layer_pull_off_force
from mdr_events.theory.layer.compliance import KERNEL_V_MAX, LAMBDA_MAX, compliance_function, kernel
from mdr_events.theory.layer.curves import layer_indentation_cycle, layer_normal_curve, layer_pull_off_curve
from mdr_events.theory.layer.force_control import PullOff, pull_off
from mdr_events.theory.layer.punch import (LAMBDA_SOLVE_MAX, SOLVE_BYTES_PER_PAIR, PunchSolution, nystrom_nodes,
                                           solve_punch)
from mdr_events.theory.layer.relations import (branch_depth, branch_normal_force, equivalent_profile, hess_elongation,
                                               normal_force, power_law_profile, power_law_profile_slope,
                                               punch_stiffness, punch_stiffness_slope, spring_stiffness_density,
                                               surface_displacement)
from mdr_events.theory.layer.slip_onset import critical_angle_on_layer, onset_depths, thin_layer_onset_depth
from mdr_events.theory.layer.tables import LAMBDA_MIN, LayerTable, layer_table, table_cache_path

__all__ = ["LAMBDA_MAX", "LAMBDA_MIN", "LAMBDA_SOLVE_MAX", "KERNEL_V_MAX", "SOLVE_BYTES_PER_PAIR", "compliance_function", "kernel", "nystrom_nodes", "PunchSolution",
           "solve_punch", "LayerTable", "layer_table", "table_cache_path", "punch_stiffness", "punch_stiffness_slope",
           "spring_stiffness_density", "hess_elongation", "surface_displacement", "equivalent_profile",
           "power_law_profile", "power_law_profile_slope", "normal_force", "branch_depth", "branch_normal_force",
           "pull_off", "PullOff", "layer_normal_curve", "layer_indentation_cycle", "layer_pull_off_curve",
           "onset_depths", "critical_angle_on_layer", "thin_layer_onset_depth", "layer_jump_off",
           "layer_jump_in_radius", "layer_pull_off_force"]
