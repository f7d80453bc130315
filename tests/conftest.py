import pytest

from mdr_events import Parameters


@pytest.fixture(scope="session")
def paper():
    return Parameters.paper()


@pytest.fixture(scope="session")
def paper_r100():
    return Parameters.paper(R=0.1)
