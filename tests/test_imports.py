"""Start-up: ``import mdr_events`` and ``mdr-events --help`` load no heavy library; what is used is loaded then.

The public names are loaded on first use (PEP 562 ``__getattr__``, as SPEC 1 lays out); ``dir``, ``__all__`` and
``from mdr_events import X`` work as if they were imported. Each check of what is loaded runs in a fresh interpreter
(this one has imported everything). How fast start-up is, is measured by ``benchmarks/bench_import.py``.
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import textwrap

import pytest

import mdr_events

#: The libraries ``import mdr_events`` must not load (plotting, SymPy, the sweep engine, SciPy's heavy parts, ...).
HEAVY = ("matplotlib", "sympy", "dask", "distributed", "zarr", "scipy", "scipy.stats", "scipy.interpolate", "xarray",
         "pandas", "numpy")


def loaded_after(code: str) -> set[str]:
    """The top-level libraries of :data:`HEAVY` and the modules of mdr_events loaded after running ``code`` in a
    fresh interpreter."""
    probe = code + "\nimport json, sys\nprint(json.dumps(sorted(sys.modules)))\n"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=300)
    modules = set(json.loads(done.stdout.splitlines()[-1]))
    return {name for name in modules if name in HEAVY or name.startswith("mdr_events")}


def test_import_loads_no_heavy_library():
    loaded = loaded_after("import mdr_events")
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))


def test_cli_help_loads_no_heavy_library_and_no_verb_options():
    loaded = loaded_after(textwrap.dedent("""
        import contextlib, io
        from mdr_events.app.cli import main
        with contextlib.redirect_stdout(io.StringIO()):
            try:
                main(["--help"])
            except SystemExit:
                pass
    """))
    assert not loaded & set(HEAVY), sorted(loaded & set(HEAVY))
    assert "mdr_events.app.inputs" not in loaded and "mdr_events.parameters" not in loaded


def test_a_verb_loads_what_it_needs_only():
    """``derive`` draws no figure (no matplotlib) and runs no simulation; parsing ``simulate`` loads no fit, no sweep
    and no plotting."""
    derive = loaded_after(textwrap.dedent("""
        import contextlib, io
        from mdr_events.app.cli import main
        with contextlib.redirect_stdout(io.StringIO()):
            assert main(["derive", "--key", "jkr_depth"]) == 0
    """))
    assert "sympy" in derive
    assert not derive & {"matplotlib", "xarray", "scipy", "dask", "mdr_events.models.simulate"}, sorted(derive)
    simulate = loaded_after(textwrap.dedent("""
        from mdr_events.app.cli import build_parser
        build_parser().parse_args(["simulate", "--scenario", "A", "--alpha", "20", "--out", "nowhere"])
    """))
    assert not simulate & {"matplotlib", "dask", "mdr_events.analysis.fit", "mdr_events.analysis.sweep",
                           "mdr_events.plotting"}, sorted(simulate)


def test_a_usage_error_loads_the_options_of_its_verb_only():
    """The hint on a file taken by a multi-value option reads the options of the verb used, not of every verb."""
    loaded = loaded_after(textwrap.dedent("""
        import contextlib, io
        from mdr_events.app.cli import main
        with contextlib.redirect_stderr(io.StringIO()):
            assert main(["run", "--no-such-option", "study.toml"]) == 2
    """))
    assert not loaded & {"numpy", "mdr_events.app.inputs", "mdr_events.analysis.fit",
                         "mdr_events.models.methods"}, sorted(loaded)


@pytest.mark.parametrize("name", mdr_events.__all__)
def test_every_public_name_resolves(name):
    namespace: dict = {}
    exec(f"from mdr_events import {name}", namespace)  # noqa: S102 - the statement users write
    assert namespace[name] is getattr(mdr_events, name)
    assert name in dir(mdr_events)


def test_every_public_name_resolves_in_a_fresh_interpreter():
    """From a fresh start (nothing loaded by another test), in the order of ``__all__``."""
    code = "import mdr_events\nfor name in mdr_events.__all__:\n    getattr(mdr_events, name)\nprint('ok')"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0 and done.stdout.strip() == "ok", done.stderr


def test_public_names_are_what_they_were():
    assert mdr_events.continuum.__name__ == "mdr_events.models.continuum"
    assert mdr_events.symbolic.__name__ == "mdr_events.theory.symbolic"
    assert mdr_events.Tolerances is mdr_events.continuum.Tolerances
    assert mdr_events.simulate.__module__ == "mdr_events.models.simulate"
    assert mdr_events.plotting.__name__ == "mdr_events.plotting"  # a subpackage, as after the eager imports
    with pytest.raises(AttributeError, match="has no attribute 'no_such_name'"):
        mdr_events.no_such_name  # noqa: B018


def test_the_registries_are_complete_whatever_is_imported():
    """A figure (and a schema) is found although only a lower layer was imported: the look-up loads its module."""
    code = textwrap.dedent("""
        import xarray as xr
        from mdr_events.io.agreement import accuracy_of
        from mdr_events.io.datasets import figure_of
        fit = xr.Dataset(attrs={"content": "fit of the model to measured curves"})
        print(figure_of(fit).__name__, type(accuracy_of(fit, "estimate")).__name__)
    """)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split()[0] == "plot_fit"


INTERRUPTED_DURING_IMPORTS = textwrap.dedent("""
    import builtins, os, signal, sys
    real_import = builtins.__import__

    def interrupting(name, *args, **kwargs):  # Ctrl-C at the first import of a heavy library
        if name.split(".")[0] in ("numpy", "scipy", "xarray", "sympy", "matplotlib"):
            builtins.__import__ = real_import
            os.kill(os.getpid(), signal.SIGINT)
        return real_import(name, *args, **kwargs)

    builtins.__import__ = interrupting
    from mdr_events.app.cli import console_main
    sys.exit(console_main())
""")


@pytest.mark.parametrize("argv", [["simulate", "--scenario", "A", "--alpha", "20", "--out", "never"],
                                  ["derive", "--key", "jkr_depth"], ["run", "no_such_study.toml"]],
                         ids=lambda argv: argv[0])
def test_ctrl_c_during_the_imports_prints_one_line(argv, tmp_path):
    """Issue 32, C6: the console script's imports of the package happen where Ctrl-C is handled: one line, 130."""
    done = subprocess.run([sys.executable, "-c", INTERRUPTED_DURING_IMPORTS, *argv], capture_output=True, text=True,
                          timeout=300, cwd=tmp_path)
    assert done.returncode == 128 + signal.SIGINT, done.stderr
    assert done.stderr == "mdr-events: interrupted (Ctrl-C); no file was left half-written\n"
    assert list(tmp_path.iterdir()) == []
