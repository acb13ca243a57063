"""The benchmark's Dask executor on a LocalCluster: the local executor's rows, and a dead worker is a row."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from conftest import ROOT
from guided_lfd import benchmark
from guided_lfd.benchmark import read_suite, run_suite

distributed = pytest.importorskip("distributed", reason="the 'dist' extra (make test installs it)")

TIMINGS = {"wall_s", "time_s", "search_time_s", "setup_time_s"}


def _slice():
    return [t for t in read_suite(ROOT / "benchmarks" / "suite.csv", ROOT) if t.domain.startswith("kitchen")][:2]


@pytest.fixture(scope="module")
def client():
    # Threads in this process: light on a 2-core machine, and the runs are processes anyway.
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as dask_client:
            yield dask_client


def _without_timings(rows):
    return [{k: v for k, v in row.to_csv().items() if k not in TIMINGS} for row in rows]


def test_dask_gives_the_local_executors_rows(client):
    suite = _slice()
    local = run_suite(suite, ["landmark"], ["consistent"], 30.0, jobs=2)
    dask = run_suite(suite, ["landmark"], ["consistent"], 30.0, executor="dask", scheduler=client)
    assert len(local) == 2 and all(r.status == "excuse-found" for r in local)
    assert _without_timings(dask) == _without_timings(local)


def test_a_chain_whose_worker_dies_is_crashed_rows_and_the_run_goes_on(client, monkeypatch):
    suite = _slice()
    real = benchmark.run_chain

    def dies_on_the_first(chain, *args, **kwargs):
        if chain[0][0].id == suite[0].id:
            raise distributed.KilledWorker(task="run_chain", last_worker=SimpleNamespace(address="inproc://w"),
                                           allowed_failures=0)
        return real(chain, *args, **kwargs)

    monkeypatch.setattr(benchmark.runner, "run_chain", dies_on_the_first)
    rows = run_suite(suite, ["landmark"], ["consistent"], 30.0, executor="dask", scheduler=client)
    by_id = {r.id: r for r in rows}
    assert by_id[suite[0].id].status == "crashed" and "worker died: KilledWorker" in by_id[suite[0].id].excuse
    assert by_id[suite[1].id].status == "excuse-found"


def test_a_dead_workers_chain_keeps_its_resumed_rows(client, monkeypatch):
    suite = _slice()[:1]
    earlier = run_suite(suite, ["landmark"], ["consistent"], 30.0, jobs=1)

    def dies(chain, *args, **kwargs):
        raise distributed.KilledWorker(task="run_chain", last_worker=SimpleNamespace(address="inproc://w"),
                                       allowed_failures=0)

    monkeypatch.setattr(benchmark.runner, "run_chain", dies)
    rows = run_suite(suite, ["landmark"], ["consistent"], 30.0, executor="dask", scheduler=client, previous=earlier)
    assert rows == earlier  # resumed, not turned into 'crashed'


def test_per_run_time_and_memory_limits_hold_under_dask(client, monkeypatch):
    """The runs a Dask worker starts are capped and killed as local ones are (the cap is set on each run)."""
    import sys

    suite = _slice()[:2]
    scripts = {
        suite[0].id: "try:\n    bytearray(4 * 1024 ** 3)\nexcept MemoryError:\n    raise SystemExit(22)\n",
        suite[1].id: "import time\ntime.sleep(30)\n",
    }
    monkeypatch.setattr(benchmark.runner, "command_line",
                        lambda task, *args: [sys.executable, "-c", scripts[task.id]])
    monkeypatch.setattr(benchmark.runner, "KILL_GRACE_S", 0.5)
    rows = run_suite(suite, ["landmark"], ["consistent"], 1.0, executor="dask", scheduler=client,
                     memory_limit_mb=1024)
    by_id = {r.id: r for r in rows}
    assert by_id[suite[0].id].status == "memout"  # 4 GB under a 1 GiB cap
    assert by_id[suite[1].id].status == "timeout" and by_id[suite[1].id].wall_s < 10
