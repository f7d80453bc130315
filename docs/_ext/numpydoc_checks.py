"""Which numpydoc checks the documentation enforces, and on what: the public API.

The public API is every name of ``mdr_events.__all__``: its functions and classes, the public methods and
properties of those classes, and the members (``__all__``) of the modules it names (``analytic``,
``power_law``, ``mindlin``, ``tabulated``, ``symbolic``, ``continuum``). ``docs/conf.py`` hands the checks to
numpydoc, which validates each of these objects during ``make docs`` (warnings, so errors under ``-W``);
``tests/test_docs.py`` runs the same validation without Sphinx (:func:`failures`), in a second.
"""

from __future__ import annotations

import enum
import importlib
import inspect
import re
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
                  "mdr_events.theory.tabulated", "mdr_events.theory.symbolic", "mdr_events.theory.layer",
                  "mdr_events.theory.layer_symbolic", "mdr_events.models.continuum")

#: Objects documented in the build that numpydoc skips: the internals' pages (``docs/api/internals``), whose
#: names are ``mdr_events.<module>.<...>`` outside the public modules (and the continuum's, the layer's, analytic's,
#: power_law's and mindlin's own submodules). Every public object passes every check: there is no list of known
#: failures, a docstring that fails breaks the build.
INTERNAL_PATTERNS = {r"^mdr_events\.(?!(" + "|".join(name.removeprefix("mdr_events.").replace(".", r"\.")
                                                      for name in ("mdr_events.theory.analytic",
                                                                   "mdr_events.theory.power_law",
                                                                   "mdr_events.theory.mindlin",
                                                                   "mdr_events.theory.tabulated",
                                                                   "mdr_events.theory.symbolic",
                                                                   "mdr_events.theory.layer",
                                                                   "mdr_events.theory.layer_symbolic",
                                                                   "mdr_events.models.continuum"))
                     + r")\.)[a-z_]+(\.[a-z_]+)*\.",
                     r"^mdr_events\.models\.continuum\.[a-z_]+\.",
                     r"^mdr_events\.theory\.layer\.[a-z_]+\.",
                     r"^mdr_events\.theory\.(analytic|power_law|mindlin)\.[a-z_]+\.",
                     r"\.__init__$",
                     r"\.[A-Z][A-Z0-9_]+$"}   # constants (FRICTION_LAWS, ...): data, no signature to check


#: The checks of an Enum's parameters that are left out: an Enum's signature is the Enum machinery's
#: (``value, names, module, qualname, type, start, boundary``), not its own; a member is looked up as
#: ``Verdict("pass")`` and each member is documented by its ``#:`` comment or the class's docstring.
ENUM_SKIPPED = {"PR01", "PR02", "PR03", "PR04", "PR05", "PR06", "PR10"}


def _is_enum(where: str) -> bool:
    """Whether the object numpydoc imports as ``where`` is an Enum class."""
    module_name, _, name = where.rpartition(".")
    try:
        obj = getattr(importlib.import_module(module_name), name)
    except (ImportError, AttributeError):
        return False
    return isinstance(obj, type) and issubclass(obj, enum.Enum)


def public_exclude() -> set[str]:
    """numpydoc's ``numpydoc_validation_exclude``: the internals and each Enum class (whose signature is the Enum
    machinery's: :data:`ENUM_SKIPPED`; :func:`failures`, which ``tests/test_docs.py`` runs, checks the rest of
    theirs), by exact name."""
    enums = {public for public, where in public_objects().items() if _is_enum(where)}
    return INTERNAL_PATTERNS | {"^" + re.escape(name) + "$" for name in enums}


def _members(cls: type) -> list[str]:
    """The public methods and properties a class defines itself."""
    names = []
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if inspect.isfunction(value) or isinstance(value, (property, classmethod, staticmethod)):
            names.append(name)
    return names


def public_objects() -> dict[str, str]:
    """Every public function, class, method and property: its public name (as the build documents it:
    ``mdr_events.Contact.replace``, ``mdr_events.theory.power_law.branch_depth``) -> the name numpydoc imports."""
    import mdr_events

    found = {}

    def add(obj, public, where):
        if isinstance(obj, type):
            found[public] = where
            for member in _members(obj):
                found[f"{public}.{member}"] = f"{where}.{member}"
        elif inspect.isfunction(getattr(obj, "__wrapped__", obj)):
            found[public] = where

    for name in mdr_events.__all__:
        obj = getattr(mdr_events, name)
        if isinstance(obj, type) or inspect.isfunction(obj):
            add(obj, f"mdr_events.{name}", f"{obj.__module__}.{obj.__qualname__}")
    for module_name in PUBLIC_MODULES:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            obj = getattr(module, name)
            if isinstance(obj, type) or inspect.isfunction(getattr(obj, "__wrapped__", obj)):   # (cached ones too)
                add(obj, f"{module_name}.{name}", f"{obj.__module__}.{obj.__qualname__}")
    return dict(sorted(found.items()))


def failures(checks=NUMPYDOC_CHECKS) -> dict[str, list[str]]:
    """Each public object whose docstring fails one of ``checks``: its public name -> the messages."""
    from numpydoc.validate import validate

    found = {}
    for public, where in public_objects().items():
        skipped = ENUM_SKIPPED if _is_enum(where) else set()
        errors = [f"{code}: {message}" for code, message in validate(where)["errors"]
                  if code in checks and code not in skipped]
        if errors:
            found[public] = errors
    return found


if __name__ == "__main__":
    result = failures()
    for name, errors in result.items():
        print(name)
        for error in errors:
            print("   ", error)
    print(f"{len(public_objects())} public objects, {len(result)} failing")
