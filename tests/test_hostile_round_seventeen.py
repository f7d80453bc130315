"""The seventeenth hostile round (issue 32): each class of what failed, with the cases that showed it.

R1, a known bug first: a ``distributed.Client`` of a malformed address (``sweep(..., scheduler="tcp://")``) made
itself the process's default client before it failed, and stayed so, "connecting" to nothing, while anything held its
error; every later ``to_netcdf`` of the process (the user's own, or a test's on the same pytest-xdist worker) then
asked it for a distributed lock and failed ("missing port number in address ''").
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import warnings

import mdr_events as me
from hostile_checks import cli_one_line
from mdr_events.app.cli import main

CONTACT = me.Contact.paper()


# --- R1: a failed dask client stayed the process's default --------------------------------------------------------

#: What a process tries, then reports as JSON: the refusal's message, the clients left (default and not closed),
#: dask's scheduler setting after, and whether a ``to_netcdf`` of its own still writes. ``error`` is held while the
#: process looks (as pytest's ``raises`` holds it): the client that failed was referenced from its traceback.
LEFT_BEHIND = textwrap.dedent("""
    import gc, json, sys, time
    import dask
    dask.config.set({"distributed.comm.timeouts.connect": sys.argv[2]})
    import numpy as np, xarray as xr
    import distributed
    import distributed.client
    import mdr_events as me
    from mdr_events.analysis import executors
    if sys.argv[3] == "unchecked":  # (the second guard alone: a client that failed is closed)
        executors.check_address = lambda scheduler: None
    start = time.monotonic()
    try:
        with executors.open_executor(sys.argv[1]):
            pass
    except ValueError as caught:
        error = caught
    refused_after = time.monotonic() - start
    gc.collect()
    open_clients = [repr(c) for c in gc.get_objects() if isinstance(c, distributed.Client) and c.status != "closed"]
    written = True
    try:
        xr.Dataset({"v": ("x", np.arange(3.0))}).to_netcdf(sys.argv[4])
    except Exception as failure:
        written = f"{type(failure).__name__}: {failure}"
    print(json.dumps({"message": str(error), "refused_after": refused_after,
                      "default": repr(distributed.client._get_global_client()), "open": open_clients,
                      "dask_scheduler": dask.config.get("scheduler", None), "written": written}))
    sys.stdout.flush()
""")

#: dask's connect timeout in the malformed cases: long, so that a client left open, which closes at the
#: interpreter's exit with twice this timeout (``Client.__del__``; 60 s with dask's default 30 s), would show as a
#: process that does not end within :data:`PROCESS_BOUND`.
CONNECT_TIMEOUT_LONG = "60s"
#: dask's connect timeout for the unreachable address: how long the refusal takes (nothing listens on port 1).
CONNECT_TIMEOUT_SHORT = "2s"
#: The time the whole process is given: an interpreter that imports mdr_events, xarray and distributed (a few seconds;
#: three times that on this shared 2-core machine under load), the refusal (at once, or after
#: CONNECT_TIMEOUT_SHORT) and the exit; well below the 120 s a client left open took to close at exit with
#: CONNECT_TIMEOUT_LONG.
PROCESS_BOUND = 50.0
#: A malformed address is refused before any connection is tried: in well under a second (the client that used to
#: be made failed at once too; the bound tells a refusal from a connect timeout, CONNECT_TIMEOUT_LONG).
REFUSAL_AT_ONCE = 5.0


def _left_behind(tmp_path, address: str, connect_timeout: str, checked: bool = True) -> tuple[dict, float]:
    """What a process that tried ``address`` left behind (:data:`LEFT_BEHIND`), and how long it ran in all."""
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-c", LEFT_BEHIND, address, connect_timeout,
                           "checked" if checked else "unchecked", str(tmp_path / "own.nc")],
                          capture_output=True, text=True, timeout=PROCESS_BOUND)
    elapsed = time.monotonic() - start
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1]), elapsed


def _nothing_left(report: dict) -> None:
    assert report["default"] == "None" and report["open"] == [], report
    assert report["dask_scheduler"] is None and report["written"] is True, report
    assert "\n" not in report["message"], report["message"]


@pytest.mark.parametrize("address, words", [
    ("tcp://", "missing port number"),
    ("tcp://127.0.0.1", "missing port number"),
    ("tcp://[::1]", "missing port number"),
    ("tcp://:8786", "names no host"),
    ("tcp://h o st:8786", "names no host (or has blanks)"),
    ("tcp://127.0.0.1:0", "port 0 is out of range"),
    ("tcp://127.0.0.1:99999", "port 99999 is out of range"),
    ("tcp://127.0.0.1:8786/x", "8786/x"),
    ("tcp://a://b:1", "it names the protocol 'tcp://a'"),
])
def test_a_malformed_address_is_refused_before_any_client_is_made(address, words):
    """The address's form is checked in dask's reading of it before a client is made, at Engine(...) already."""
    with pytest.raises(ValueError) as raised:
        me.Engine(scheduler=address)
    message = str(raised.value)
    assert f"scheduler={address!r} is not allowed" in message and words in message, message
    assert "allowed: an address tcp://host:port" in message and "\n" not in message, message


@pytest.mark.parametrize("checked", [True, False], ids=["form-checked", "client-closed"])
def test_a_malformed_address_leaves_no_client_behind(tmp_path, checked):
    """``sweep(..., scheduler="tcp://")``: refused in one line, and after it no default client, none open, dask's
    scheduler as it was, the process's own ``to_netcdf`` writes, and the process ends at once. ``client-closed``
    skips the form's check, so that a client is made and fails: the one it left as default is closed."""
    report, elapsed = _left_behind(tmp_path, "tcp://", CONNECT_TIMEOUT_LONG, checked)
    _nothing_left(report)
    assert report["refused_after"] < REFUSAL_AT_ONCE, report
    assert ("is not allowed: missing port number" if checked else "cannot be reached") in report["message"], report
    assert elapsed < PROCESS_BOUND


def test_an_unreachable_address_leaves_no_client_behind(tmp_path):
    """A well-formed address where nothing listens: refused in one line after the connect timeout, nothing left."""
    report, elapsed = _left_behind(tmp_path, "tcp://127.0.0.1:1", CONNECT_TIMEOUT_SHORT)
    _nothing_left(report)
    assert "scheduler='tcp://127.0.0.1:1' cannot be reached" in report["message"], report
    assert elapsed < PROCESS_BOUND


# --- R2: the kernels (run_discrete, run_continuum) read their arguments as they came: a path that was not one,
# limits or tolerances that were not, a spacing of 0 or a string failed deep inside (AttributeError,
# ZeroDivisionError, NumPy's "zero-size array" or "negative dimensions") ----------------------------------------------

def _kernel_calls():
    from mdr_events.models.continuum import run_continuum
    from mdr_events.models.discrete import run_discrete
    from mdr_events.models.kernel_model import KernelModel

    paper = me.Parameters.paper()
    path = me.Path(np.array([(0.0, 0.0), (0.0, 3e-4), (1e-4, -1e-4)]), 1e-6)
    return [
        (lambda: run_discrete(paper, None, 1e-6, 0.1), "paths=None"),
        (lambda: run_discrete(paper, path, 1e-6, 0.1), "paths=Path("),
        (lambda: run_discrete(paper, [], 1e-6, 0.1), "paths=[]"),
        (lambda: run_discrete(paper, [1], 1e-6, 0.1), "paths[0]=1 (int)"),
        (lambda: run_discrete(paper, [path], "1e-6", 0.1), "dx='1e-6' (str)"),
        (lambda: run_discrete(paper, [path], 0, 0.1), "dx=0"),
        (lambda: run_discrete(paper, [path], 1e-6, -1), "dt=-1"),
        (lambda: run_discrete(paper, [path], 1e-6, float("nan")), "dt=nan"),
        (lambda: run_discrete(paper, [path], 1e-6, 0.1, limits="big"), "limits='big' (str)"),
        (lambda: run_discrete(KernelModel(None), [path], 1e-6, 0.1), "model.params=None"),
        (lambda: run_continuum(paper, [path, "x"]), "paths[1]='x' (str)"),
        (lambda: run_continuum(paper, [path], times="x"), "times='x'"),
        (lambda: run_continuum(paper, [path], times=0), "times=0"),
        (lambda: run_continuum(paper, [path], times=-5), "times=-5"),
        (lambda: run_continuum(paper, [path], times=True), "times=True"),
        (lambda: run_continuum(paper, [path], times=[1.0, 0.5]), "times=[1.0, 0.5]"),
        (lambda: run_continuum(paper, [path], tolerances=None), "tolerances=None"),
        (lambda: run_continuum(paper, [path], tolerances=1e-6), "tolerances=1e-06"),
        (lambda: run_continuum(KernelModel("paper"), [path]), "model.params='paper' (str)"),
    ]


@pytest.mark.parametrize("index", range(len(_kernel_calls())))
def test_the_kernels_name_an_argument_of_the_wrong_type_or_value(index):
    call, named = _kernel_calls()[index]
    with pytest.raises((TypeError, ValueError)) as raised:
        call()
    message = str(raised.value)
    assert named in message and "allowed" in message and "\n" not in message, message


def test_the_kernels_still_take_what_they_took():
    """A tuple of paths, a NumPy integer of samples and a grid of times run as before."""
    from mdr_events.models.continuum import run_continuum

    path = me.Path(np.array([(0.0, 0.0), (0.0, 3e-4), (1e-4, -1e-4)]), 1e-6)
    assert run_continuum(me.Parameters.paper(), (path,), times=np.int64(3))["time"].size == 3
    assert list(run_continuum(me.Parameters.paper(), [path], times=[0.0, 1.0])["time"]) == [0.0, 1.0]


# --- R3: `mdr-events derive` (every relation, as the README shows it) exited 2: two relations of the rate-dependent
# adhesion law were derived and listed but not found by key ("key='let_go_depth' is not allowed") ---------------------

def test_every_relation_derive_lists_is_found_by_its_key():
    from mdr_events.theory import symbolic

    families = {symbolic.POWER_LAW_KEYS: symbolic.derive_power_law_model,
                symbolic.FRICTION_KEYS: symbolic.derive_friction_model,
                symbolic.ADHESIVE_FRICTION_KEYS: symbolic.derive_adhesive_friction_model,
                symbolic.RATE_ADHESION_KEYS: symbolic.derive_rate_dependent_adhesion}
    for keys, derive in families.items():  # (each family's keys route relation(key) to it)
        assert set(keys) == set(derive()), derive.__name__
    for key, relation in symbolic.relations().items():
        assert symbolic.relation(key).key == key == relation.key


def test_derive_prints_every_relation(capsys):
    from mdr_events.theory import symbolic

    assert main(["derive"]) == 0
    out = capsys.readouterr().out
    assert [line.split(":")[0][2:].split(" ")[0] for line in out.splitlines() if line.startswith("# ")] == \
        list(symbolic.relations())


# --- R4: the continuum under Coulomb's law alone on a cone at mu ~ 1e6 (scenario B, 20°) ran for tens of minutes: the
# compressed zone's slip zone at the shrinking edge opened and left again every 4e-9 s (1e-12 of the time, the event
# times' resolution) from t = 1177 s on, 4e5 spans to the pull-off ------------------------------------------------

# (The refusal these cases were given was lifted in round eighteen, S1: the chatter was a zone of no width laid out at
# the shrinking edge, a fault of the layout, not physics; tests/test_hostile_round_eighteen.py runs them and checks them
# against the discrete model's convergence.)


@pytest.mark.parametrize("profile, mu, alpha", [
    (me.PowerLaw(0.5, 1.0), 2e6, 20.0),  # (next to the chatter: no chatter)
    pytest.param(me.PowerLaw(2e5, 3.0), 1e5, 80.0, marks=pytest.mark.slow),  # (3215 short spans in a row, then on:
    # the most seen in a run that ends, which MAX_CHATTER_SPANS lets run; about 5 s of CPU)
])
def test_a_run_with_short_spans_that_ends_still_runs(profile, mu, alpha):
    contact = me.Contact(CONTACT.elastomer, profile, CONTACT.adhesion, me.FrictionLaw("coulomb", mu=mu))
    run = me.simulate(contact, "B", alpha, "continuum")
    inside = np.isfinite(run["indentation_depth"].values)
    assert np.all(np.isfinite(run["tangential_force"].values[inside]))


# --- R5: a [sweep] table with both grid and sets (or neither) was told it "needs one of grid and sets", which reads as
# "give one more", without saying which were given or what is allowed ---------------------------------------------------

@pytest.mark.parametrize("tables, given", [
    ('grid = { tau0 = [3e4] }\nsets = [{}]\n', "both given"),
    ('', "neither given"),
])
def test_a_sweep_with_grid_and_sets_says_which_were_given(capsys, tmp_path, tables, given):
    study = tmp_path / "study.toml"
    study.write_text('[sweep]\nscenario = "A"\nalpha = 20\nscheduler = "serial"\n' + tables
                     + '[output]\ndirectory = "out"\n')
    err = cli_one_line(capsys, ["sweep", str(study)])
    assert given in err and "allowed: exactly one of them" in err


# --- R6: fit_rate_adhesion on a curve that does not see v_ref (a constant force) ended in a raw OverflowError ("math
# range error"): its log-scaled interval's upper end, exp of the half-width, beyond the double range ------------------

def test_a_rate_fit_that_does_not_see_a_parameter_gives_an_open_interval():
    paper = me.Parameters.paper()
    vertical = me.Path(np.array([(0.0, 0.0), (0.0, paper.d_max), (0.0, -200e-6)]), speed=1e-6)
    times = np.linspace(vertical.first_contact_time(), vertical.duration, 60)
    law = me.RateDependentAdhesion(paper.dgamma0, paper.dgamma1, 1e-6, 0.6)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fitted = me.fit_rate_adhesion([me.RateMeasurement(vertical, times, np.ones_like(times))], paper, law)
    upper = fitted["interval_upper"].sel(parameter="v_ref")
    assert float(upper) == np.inf and float(fitted["interval_lower"].sel(parameter="v_ref")) >= 0.0
    assert not np.any(np.isnan(fitted["standard_error"].values))
