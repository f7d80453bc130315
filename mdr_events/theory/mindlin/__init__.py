"""The friction laws in closed form: tangential loading at a constant depth (Cattaneo–Mindlin, Masing's loops) and
the slip onset of proportional loading (scenario A).

At a constant depth ``d`` without adhesion every spring in contact keeps its cap (the friction law's,
:mod:`mdr_events.contact.friction`): ``ū(ξ) = K a + κ (d − g(ξ))`` with ``K a`` the part of ``τ0`` (13) and
``κ = μ E*/G*`` Coulomb's (:func:`coulomb_cap_ratio`). Each spring is then a play operator of its own cap,
and, from rest, a tangential shift ``u_x`` of the indenter gives the *virgin curve*

    ``F₀(u_x) = 2G* a min(u_x, K a) + μ (F_N(d) − F_N(d − max(u_x − K a, 0)/κ))``

(:func:`virgin_force`; the Coulomb part is Cattaneo–Mindlin's, in the form of Jäger and Ciavarella, derived
in :func:`mdr_events.theory.symbolic.derive_friction_model`; the two parts add because the Coulomb caps all
sit above ``K a``). Any back-and-forth motion from rest then follows Masing's rules with memory
(:func:`tangential_force`): after a reversal at ``(x_r, F_r)`` the force is ``F_r + 2 F₀((x − x_r)/2)``
until the branch reaches the point its predecessor started from, where that one resumes; the first
unloading from ``(X, F₀(X))`` runs to ``(−X, −F₀(X))`` and rejoins the virgin curve (Mindlin & Deresiewicz
1953; the loops of a fretting contact).

With adhesion (Heß's rule, (8)–(9)) the springs beyond ``x_c``, where ``g(x_c) = d``, are in tension and hold no
Coulomb shift: the cap is ``K a + κ max(d − g(ξ), 0)``, with ``a >= x_c`` the contact radius that the history pins
between the branches (the ``radius`` argument; default the ``Δγ0`` branch's, indented to ``d``). The virgin curve is
then ``2G* a min(u_x, K a) + μ (F_N^H(d) − F_N^H(d − max(u_x − K a, 0)/κ))`` with ``F_N^H`` the force of the
compressed zone alone, the non-adhesive one of the depth (derived in
:func:`mdr_events.theory.symbolic.derive_adhesive_friction_model`): Coulomb's part does not depend on ``Δγ`` at all,
and full slip is ``τ0 π a² + μ F_N^H(d)``, not ``μ F_N``, which the tensile springs lower.

Along scenario A's path (14), ``x = d / tan α`` from first contact without adhesion, a spring attached at depth
``d_ξ`` holds the shift ``(d − d_ξ)/tan α`` against the cap ``K a + κ (d − d_ξ)``: the Coulomb part grows with the
shift, so where ``cot α <= κ`` no spring ever slides, and where ``cot α > κ`` the centre's spring slides first, when
``(cot α − κ) d = K a(d)``: the paper's (17) at the angle ``α'`` of ``cot α' = cot α − κ`` (:func:`d_crit_A`,
:func:`critical_angle_A`). Coulomb's law alone (``K = 0``) then slides from first contact (the angle of friction
``tan α = 1/κ = G*/(μ E*)``).

Scenario B without adhesion (in vertically to ``d_max``, every spring anchored at ``x = 0``): out at ``α`` all
springs share the shift ``(d_max − d)/tan α``, and the edge's cap is the smallest, ``K a`` (its compression is
zero): the onset is the paper's (20) for any ``τ0`` part, at once (``d_max``) for Coulomb's alone
(:func:`d_crit_B`). Further in at ``α`` the old edge's cap is ``K a + κ (d − d_max)`` against the shift
``(d − d_max)/tan α``: (20)'s "+" branch at ``α'`` (:func:`d_crit_B_indentation`).

One closed form per function for each friction law (virgin curves, Masing's loops, full slip, the onsets of scenarios
A and B), each with its numpydoc sections; the flat punch's own (every spring compressed by ``d`` alike: one play
operator, :func:`flat_punch_force`) are :mod:`mdr_events.theory.flat_punch`'s, filed by
:func:`mdr_events.theory.kinds.theory_of` (``friction_forms``).

The package holds one idea per module, and this module lists the public names (``__all__``) where users and the
documentation import them: the caps and the contact they act on (``caps``), tangential loading at a constant depth
(``loading``), the slip onsets and critical angles (``onset``).
"""

from __future__ import annotations

from mdr_events.theory.flat_punch import tangential_force as flat_punch_force
from mdr_events.theory.mindlin.caps import coulomb_cap_ratio
from mdr_events.theory.mindlin.loading import (full_slip_force, full_slip_shift, loop_energy, tangential_force,
                                               virgin_force)
from mdr_events.theory.mindlin.onset import (adhesive_onset_A_is_non_adhesive, critical_angle_A, critical_angle_B,
                                             critical_angle_B_indentation, d_crit_A, d_crit_B, d_crit_B_indentation)

__all__ = ["coulomb_cap_ratio", "full_slip_shift", "full_slip_force", "virgin_force", "tangential_force", "loop_energy",
           "flat_punch_force", "adhesive_onset_A_is_non_adhesive",
           "d_crit_A", "critical_angle_A", "d_crit_B", "critical_angle_B", "d_crit_B_indentation",
           "critical_angle_B_indentation"]
