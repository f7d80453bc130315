"""``.. study-format-tables::``: the study file's tables and keys, generated from the schema the reader checks
(:data:`mdr_events.app.study_format.SCHEMA`), so that the reference page cannot drift from the code."""

from __future__ import annotations

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.util.docutils import SphinxDirective


def _unit(table: str, key: str) -> str:
    from mdr_events.limits import LIMIT_UNITS
    from mdr_events.parameters import PARAMETER_UNITS

    units = {"parameters": PARAMETER_UNITS, "limits": LIMIT_UNITS}.get(table, {})
    unit = units.get(key, "")
    return str(unit) if unit else ""


def schema_lines() -> list[str]:
    """The reStructuredText of one list-table per study table."""
    from mdr_events.app.study_format import _KINDS, KEY_NOTES, REQUIRED_TABLES, SCHEMA

    lines = []
    for table, keys in SCHEMA.items():
        need = "required" if table in REQUIRED_TABLES else "optional"
        lines += [f".. list-table:: ``[{table}]`` ({need} table)", "   :header-rows: 1",
                  "   :widths: 18 12 50 20", "", "   * - key", "     - required", "     - allowed value",
                  "     - unit"]
        for key, (kind, required) in keys.items():
            allowed = _KINDS[kind][1]
            if (table, key) in KEY_NOTES:
                allowed += f": {KEY_NOTES[table, key]}"
            allowed = allowed.replace("*", r"\*").replace("`", "'")
            unit = _unit(table, key)
            lines += [f"   * - ``{key}``", f"     - {'yes' if required else 'no'}", f"     - {allowed}",
                      f"     - {unit or ''}"]
        lines.append("")
    return lines


class StudyFormatTables(SphinxDirective):
    has_content = False

    def run(self):
        container = nodes.container()
        self.state.nested_parse(StringList(schema_lines(), source="mdr_events.app.study_format.SCHEMA"),
                                self.content_offset, container)
        return container.children


def setup(app):
    app.add_directive("study-format-tables", StudyFormatTables)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
