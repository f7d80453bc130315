"""The reproduction of section 4 of the paper: ``mdr-events reproduce`` writes ``results/`` and its README.

One module per section (:class:`~mdr_events.reproduction.section.Section`: its steps, its files, its Markdown), in
the report's order in :data:`~mdr_events.reproduction.runner.SECTIONS`:

- :mod:`.phase_diagrams`: Fig. 9a and 9b;
- :mod:`.critical_angles`: scenario A's critical angles beside the paper's, scenario B's;
- :mod:`.cross_check`: slip onset three ways;
- :mod:`.figures`: Fig. 8 and 10, and the four differences of section 4.2 read off them (:mod:`.differences`);
- :mod:`.convergence`: the discrete model's convergence;
- :mod:`.fretting`: fretting at ``d_max``, the energy per cycle beside its closed form;
- :mod:`.fit_demo`: fitting to synthetic measurements;
- :mod:`.universal`: the universal map over the dimensionless groups;
- :mod:`.profiles`: other indenters;
- :mod:`.mindlin`: Coulomb's law against Cattaneo–Mindlin;
- :mod:`.parameter_table`: the parameters.

:mod:`.runner` computes, writes and renders them and counts the steps; :mod:`.readme` frames the report (title, list
of files, software); :mod:`.markdown` holds the one table helper every section uses. The package sits at the ``app``
layer: it imports from every layer below and from :mod:`mdr_events.app.result_files`. Importing it registers the
schemas of the studies it writes (fretting, Cattaneo–Mindlin), so that ``open_result`` reads their files.
"""

from mdr_events.reproduction.runner import COMPUTE_STEPS, SECTIONS, compute, report_text, reproduce, step_count
from mdr_events.reproduction.section import Reproduction, Section, Step

__all__ = ["reproduce", "compute", "report_text", "step_count", "SECTIONS", "COMPUTE_STEPS", "Section", "Step",
           "Reproduction"]
