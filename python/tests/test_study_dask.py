"""Studies on Dask clusters (docs/studies.md): a local cluster of 2 worker
processes, a scheduler and 2 workers started as separate processes on the
loopback address, and a worker killed in the middle of a study; each gives
the serial runs' outputs bit for bit. Skipped only without Dask
(Debian's python3-distributed)."""

import os
import signal
import socket
import subprocess
import sys

import pytest

import flexmb

distributed = pytest.importorskip("distributed", reason="Dask (Debian's python3-distributed) is not importable")

DASK_TIMEOUT = 50  # s, every study and cluster call here ends by then


def lengths_study(tmp_path, source_dir, count, t_end=6.0):
    """The pendulum over `count` lengths (a study file in tmp_path)."""
    model = os.path.join(source_dir, "examples", "studies", "pendulum.yaml")
    values = ", ".join(str(0.2 + 0.1 * i) for i in range(count))
    path = tmp_path / "lengths.yaml"
    path.write_text(f"""model: {model}
options: {{t_end: {t_end}}}
timeout: 30
parameters:
  length: {{path: "bodies[name=bob].center_of_mass[1]", scale: -1, values: [{values}]}}
outputs: {{period: period(angle.value), max_rate: max(angle.rate), steps: summary.steps}}
""")
    return path


@pytest.fixture(scope="module")
def lengths(tmp_path_factory, source_dir_module, cli_module):
    """The study of 6 lengths and its rows run serially (the reference of every test here)."""
    folder = tmp_path_factory.mktemp("lengths")
    path = lengths_study(folder, source_dir_module, 6)
    return path, flexmb.study(path, folder / "serial", workers=0, cli=cli_module)


def outputs(table):
    """The rows without the wall time (which differs from run to run)."""
    return [{k: v for k, v in r.items() if k != "wall_time_s"} for r in table]


def test_local_cluster_equals_serial(cli, lengths, tmp_path):
    path, serial = lengths
    parallel = flexmb.study(path, tmp_path / "dask", workers=2, cli=cli, timeout=DASK_TIMEOUT)
    assert outputs(parallel) == outputs(serial)
    assert parallel.column("status") == ["ok"] * 6
    csv_serial = (path.parent / "serial" / "study.csv").read_text().splitlines()
    csv_dask = (tmp_path / "dask" / "study.csv").read_text().splitlines()
    assert [line.rsplit(",", 1)[0] for line in csv_dask] == [line.rsplit(",", 1)[0] for line in csv_serial]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_scheduler_and_workers_as_processes(cli, lengths, tmp_path):
    path, serial = lengths
    address = f"tcp://127.0.0.1:{free_port()}"
    dask = [sys.executable, "-m", "distributed.cli.dask_scheduler"]
    env = dict(os.environ, FLEXMB_CLI=cli)
    procs = [subprocess.Popen([*dask, "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1], "--no-dashboard"],
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        for _ in range(2):
            procs.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                                           "--nthreads", "1", "--no-dashboard", "--no-nanny"],
                                          env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        with distributed.Client(address, timeout=DASK_TIMEOUT) as client:
            client.wait_for_workers(2, timeout=DASK_TIMEOUT)
        table = flexmb.study(path, tmp_path / "remote", scheduler=address, cli=cli, timeout=DASK_TIMEOUT)
    finally:
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
    assert outputs(table) == outputs(serial)


def test_a_killed_worker_has_its_runs_redone(cli, lengths, tmp_path):
    path, serial = lengths
    killed = {}

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=50) as cluster, \
            distributed.Client(cluster, timeout=DASK_TIMEOUT) as client:
        def kill_a_busy_worker(row):
            if killed:
                return
            busy = {w: keys for w, keys in client.processing().items() if keys}
            if not busy:
                return
            worker = sorted(busy)[0]
            pid = client.run(os.getpid, workers=[worker])[worker]
            killed.update(worker=worker, pid=pid, keys=list(busy[worker]))
            os.kill(pid, signal.SIGKILL)

        table = flexmb.study(path, tmp_path / "dask", scheduler=client, cli=cli, timeout=DASK_TIMEOUT,
                             on_row=kill_a_busy_worker)
    assert killed and killed["keys"], "no worker was busy when the first run finished"
    lost = sorted(int(k.split("-")[3]) for k in killed["keys"])  # keys flexmb-study-run-N-...
    assert all(table[i]["status"] == "ok" for i in lost)  # the killed worker's runs, redone elsewhere
    assert table.column("status") == ["ok"] * 6
    assert outputs(table) == outputs(serial)
