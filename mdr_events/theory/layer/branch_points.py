r"""The points of a branch on a layer: the jump-off under depth control, the radius at first touch and the pull-off
force under force control (what :func:`mdr_events.jump_off`, :func:`~mdr_events.theory.analytic.jump_in_radius` and
:func:`mdr_events.pull_off_force` run for a contact on a layer of finite thickness).

Part of :mod:`mdr_events.theory.layer` (the relations (L1)–(L5) are stated there). On the layer the branch of the
work ``Δγ`` is ``d(a) = g(a) − Δl(a)`` (generalised (9), ``Δl = sqrt(4π a Δγ / K'(a))``) and its force
``F_N = F₀(a) − K(a) Δl(a)`` (generalised (10)). The jump-off under depth control is its least depth
(``∂d/∂a = 0``), the first touch the stable radius at ``d = 0`` and the pull-off under force control the least
force (:func:`~mdr_events.theory.layer.force_control.pull_off`). None has a closed form on a layer: each is found in
``a`` on the layer's tables. At ``h = inf`` they are the half-space's closed forms of
:mod:`mdr_events.theory.analytic` (the tests check it at ``h = 1e9`` m).
"""

from __future__ import annotations

from typing import Any, Callable, TypeVar

import numpy as np

from mdr_events.contact.model import Contact
from mdr_events.parameters import PAPER_D_MAX
from mdr_events.theory.job import rate_independent
from mdr_events.theory.layer.compliance import LAMBDA_MAX
from mdr_events.theory.layer.branch_scan import branch_jump_off, check_scales, layer_material, stable_radius
from mdr_events.theory.layer.force_control import pull_off
from mdr_events.theory.layer.relations import branch_normal_force
from mdr_events.validation import check_real

__all__ = ["layer_jump_off", "layer_jump_in_radius", "layer_pull_off_force", "check_branch_contact"]

_Point = TypeVar("_Point")


def _within_tables(compute: Callable[[], _Point], contact: Contact, work: float, what: str) -> _Point:
    """``compute()``, its inputs checked (:func:`check_branch_contact`): the one ``ValueError`` left is a point beyond
    the tables, said in one line naming the layer and the work (the scans' own words named a depth or ``a0``)."""
    try:
        return compute()
    except ValueError:
        raise ValueError(f"contact.layer={contact.layer!r} is not allowed in {what}(work_of_adhesion={work!r}): the "
                         f"point lies beyond the tables' a/h = {LAMBDA_MAX:g}; allowed: a thicker layer "
                         "or a smaller work of adhesion") from None


def check_branch_contact(contact: Any, work_of_adhesion: float, what: str) -> tuple[Contact, float]:
    """What the points of a branch on a layer take, checked before they are computed: a
    :class:`~mdr_events.Contact` of a paraboloid or power law (:func:`~mdr_events.theory.layer.branch_scan.layer_material`),
    the paper's rate-independent adhesion law, a work of adhesion ``≥ 0`` and scales within double precision
    (:func:`~mdr_events.theory.layer.branch_scan.check_scales`, with the work asked and the paper's depth, as
    :func:`~mdr_events.layer_pull_off_curve` checks its contact).

    Parameters
    ----------
    contact : Contact
        A contact on a layer of finite thickness (the half-space too).
    work_of_adhesion : float
        ``Δγ`` of the branch (J/m²).
    what : str
        The function asked, named in the errors.

    Returns
    -------
    tuple of (Contact, float)
        The contact and the work as a float.

    Raises
    ------
    TypeError
        ``contact`` not a Contact, or its adhesion law rate-dependent; a work that is not a real number.
    ValueError
        Another indenter, a work not a finite number ``≥ 0``, or scales beyond the double range; in one line.
    """
    layer_material(contact)
    rate_independent(contact, f"{what} on a layer")
    work = check_real("work_of_adhesion", work_of_adhesion, "a finite number >= 0 (J/m²)", lambda value: value >= 0.0)
    check_scales(contact.replace(**{"adhesion.dgamma0": work, "adhesion.dgamma1": work}), PAPER_D_MAX, what)
    return contact, work


def layer_jump_off(contact: Contact, work_of_adhesion: float) -> dict[str, float]:
    r"""The jump-off under depth control on the contact's layer: the least depth of the branch of ``Δγ``.

    .. math:: \frac{\partial d}{\partial a} = 0 \ \text{on}\ d(a) = g(a) - \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}}
              \quad (9), \qquad F_N = F_0(a) - K(a)\,\Delta l(a) \quad (10)

    (on the half-space ``a = (πR²Δγ/E*)^(1/3)/2``, ``F_N = −(5/6)πRΔγ`` for the paraboloid).

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer and layer (the adhesion law rate-independent).
    work_of_adhesion : float
        ``Δγ`` (J/m², ``≥ 0``): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    dict of str to float
        ``contact_radius`` (m), ``depth`` (m) and ``normal_force`` (N) at the jump-off; 0 each without adhesion
        (the branch ``d = g(a)`` rises from the first touch).

    Raises
    ------
    TypeError, ValueError
        As :func:`check_branch_contact`; a jump-off beyond the tables (``a/h > 64``).
    """
    contact, work = check_branch_contact(contact, work_of_adhesion, "jump_off")
    depth, radius = _within_tables(lambda: branch_jump_off(contact, work), contact, work, "jump_off")
    E_star, nu, layer = layer_material(contact)
    force = float(branch_normal_force(radius, contact.indenter, E_star, nu, work, layer)) if work > 0.0 else 0.0
    return {"contact_radius": radius, "depth": depth, "normal_force": force}


def layer_jump_in_radius(contact: Contact, work_of_adhesion: float) -> float:
    r"""The contact radius at first touch on the contact's layer: the stable branch of ``Δγ`` at ``d = 0``.

    .. math:: g(a) = \sqrt{\frac{4\pi a\,\Delta\gamma}{K'(a)}} \quad (9)\ \text{at}\ d = 0, \ a \ge a_\mathrm{jo}

    (on the half-space ``a = (2πR²Δγ/E*)^(1/3)`` for the paraboloid).

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer and layer (the adhesion law rate-independent).
    work_of_adhesion : float
        ``Δγ`` (J/m², ``≥ 0``): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The contact radius (m) at first touch; 0 without adhesion.

    Raises
    ------
    TypeError, ValueError
        As :func:`check_branch_contact`; a radius beyond the tables (``a/h > 64``).
    """
    contact, work = check_branch_contact(contact, work_of_adhesion, "jump_in_radius")
    return _within_tables(lambda: float(stable_radius(contact, work, np.array([0.0]))[0]), contact, work,
                          "jump_in_radius")


def layer_pull_off_force(contact: Contact, work_of_adhesion: float) -> float:
    r"""The pull-off force under force control on the contact's layer: the least force along the branch of ``Δγ``.

    .. math:: F_\mathrm{po} = \min_a\,[F_0(a) - K(a)\,\Delta l(a)] \qquad (10)

    (``−(3/2)πΔγR`` for the paraboloid on the half-space, ``−3πΔγR`` on a thin incompressible bonded layer);
    :func:`~mdr_events.theory.layer.force_control.pull_off`, as :func:`~mdr_events.layer_pull_off_curve` at the
    contact's thickness.

    Parameters
    ----------
    contact : Contact
        A paraboloid or power law with its elastomer and layer (the adhesion law rate-independent).
    work_of_adhesion : float
        ``Δγ`` (J/m², ``≥ 0``): ``Δγ0`` for the branch of indentation, ``Δγ1`` for that of pull-off.

    Returns
    -------
    float
        The pull-off force (N, negative; 0 without adhesion: the least force of ``F_N ≥ 0`` is at the first touch).

    Raises
    ------
    TypeError, ValueError
        As :func:`check_branch_contact`; a pull-off beyond the tables (``a/h > 64``).
    """
    contact, work = check_branch_contact(contact, work_of_adhesion, "pull_off_force")
    if work == 0.0:
        return 0.0
    E_star, nu, layer = layer_material(contact)
    return _within_tables(lambda: pull_off(contact.indenter, E_star, nu, work, layer).force, contact, work,
                          "pull_off_force")
