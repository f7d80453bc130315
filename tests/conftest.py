import os
import sys

import pytest
from hypothesis import settings

from mdr_events import Parameters

# CI runs the property tests on a fixed set of examples (derandomized: the same run every time, no
# example database written into the clone); HYPOTHESIS_PROFILE=explore draws fresh examples, five
# times as many (tests/models/test_properties.py scales its counts), to hunt for new counterexamples.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("explore", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture(scope="session")
def paper():
    return Parameters.paper()


@pytest.fixture(scope="session")
def paper_r100():
    return Parameters.paper(R=0.1)


@pytest.fixture(autouse=True)
def close_figures():
    """Close every matplotlib figure a test left open (only if pyplot was imported at all: importing it here
    would pick a backend for every test)."""
    yield
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close("all")
