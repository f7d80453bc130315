"""Which numpydoc checks the documentation enforces, and on what: the public API.

The public API is every name of ``mdr_events.__all__``: its functions and classes, the public methods and
properties of those classes, and the members (``__all__``) of the modules it names (``analytic``,
``power_law``, ``mindlin``, ``tabulated``, ``symbolic``, ``continuum``). ``docs/conf.py`` hands the checks to
numpydoc, which validates each of these objects during ``make docs`` (warnings, so errors under ``-W``);
``tests/test_docs.py`` runs the same validation without Sphinx (:func:`failures`), in a second.
"""

from __future__ import annotations

import importlib
import inspect
import types

#: The checks (numpydoc's codes): a docstring exists and has a summary; every parameter is documented, with
#: a type, in the signature's order and nothing else; a function returns through a documented Returns (or
#: Yields) section; the sections are known and in numpydoc's order. Left out: the style checks (summary
#: on one line, imperative mood, blank lines), See Also and Examples sections (the tutorials hold examples).
NUMPYDOC_CHECKS = {
    "GL06", "GL07", "GL08",
    "SS01",
    "PR01", "PR02", "PR03", "PR04", "PR05", "PR06", "PR10",
    "RT01", "RT03",
    "YD01",
}

#: The modules of ``mdr_events.__all__`` whose own ``__all__`` is public too.
PUBLIC_MODULES = ("mdr_events.theory.analytic", "mdr_events.theory.power_law", "mdr_events.theory.mindlin",
                  "mdr_events.theory.tabulated", "mdr_events.theory.symbolic", "mdr_events.models.continuum")

#: Objects documented in the build that are not public (the internals' pages, ``docs/api/internals``):
#: their names are ``mdr_events.<module>.<...>`` outside the public modules. numpydoc skips them.
PUBLIC_EXCLUDE = {r"^mdr_events\.(?!(" + "|".join(name.removeprefix("mdr_events.").replace(".", r"\.")
                                                  for name in PUBLIC_MODULES) + r")\.)[a-z_]+(\.[a-z_]+)*\.",
                  r"\.__init__$"}


def _members(cls: type) -> list[str]:
    """The public methods and properties a class defines itself."""
    names = []
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if inspect.isfunction(value) or isinstance(value, (property, classmethod, staticmethod)):
            names.append(name)
    return names


def public_objects() -> list[str]:
    """The dotted names (as numpydoc imports them) of every public function, class, method and property."""
    import mdr_events

    names = []

    def add(obj, name):
        if isinstance(obj, type):
            names.append(name)
            names.extend(f"{name}.{member}" for member in _members(obj))
        elif inspect.isfunction(obj) or inspect.isbuiltin(obj):
            names.append(name)

    for name in mdr_events.__all__:
        obj = getattr(mdr_events, name)
        if isinstance(obj, types.ModuleType):
            continue
        if isinstance(obj, type) or inspect.isfunction(obj):
            add(obj, f"{obj.__module__}.{obj.__qualname__}")
    for module_name in PUBLIC_MODULES:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            obj = getattr(module, name)
            if isinstance(obj, type) or inspect.isfunction(obj):
                add(obj, f"{obj.__module__}.{obj.__qualname__}")
    return sorted(set(names))


def failures(checks=NUMPYDOC_CHECKS) -> dict[str, list[str]]:
    """Each public object whose docstring fails one of ``checks``: its name -> the messages."""
    from numpydoc.validate import validate

    found = {}
    for name in public_objects():
        errors = [f"{code}: {message}" for code, message in validate(name)["errors"] if code in checks]
        if errors:
            found[name] = errors
    return found


if __name__ == "__main__":
    result = failures()
    for name, errors in result.items():
        print(name)
        for error in errors:
            print("   ", error)
    print(f"{len(public_objects())} public objects, {len(result)} failing")
