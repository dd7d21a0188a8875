"""penumbra.dask on a real LocalCluster (two worker processes on loopback): the merged
results equal the single-process run byte for byte, each worker loads a scene once, a killed
worker does not change the result, and a penumbra error fails the job with its message."""

import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

import penumbra  # noqa: E402
import penumbra.dask as pd  # noqa: E402
from conftest import BINARY, scene_path  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       host="127.0.0.1", dashboard_address=None)
    with distributed.Client(cluster) as connected:
        yield connected
    cluster.close()


def test_sun_hours_on_the_cluster_is_the_single_process_run(client, city):
    single = penumbra.Scene.load(city).sun_hours(date="2026-03-21", step="1h", exact=True)
    spread = pd.sun_hours(city, date="2026-03-21", step="1h", client=client, exact=True)
    assert spread.to_json() == single.to_json()
    assert len(spread.faces) == len(single.faces) > 60


def test_workplane_on_the_cluster_is_the_single_process_run(client):
    name = scene_path("office.json")
    single = penumbra.Scene.load(name).workplane(0.8, 0.25)
    spread = pd.workplane(name, 0.8, 0.25, client=client, tasks=7)
    assert np.array_equal(spread.points, single.points)
    assert np.array_equal(spread.values, single.values)
    for light in single.per_light:
        assert np.array_equal(spread.per_light[light], single.per_light[light])
    points = single.points[::5]
    per_light = pd.illuminance(name, points, client=client, per_light=True)
    assert np.array_equal(per_light["total"], single.values[::5])


def test_each_worker_loads_a_scene_once(client, city):
    pd.sun_hours(city, date="2026-03-21", step="2h", client=client, tasks=12)
    loads = client.run(pd.worker_loads)
    scenes = client.run(lambda: len(__import__("penumbra.dask").dask._scenes))
    assert loads == scenes  # one load per scene per worker, however many tasks it ran
    assert sum(loads.values()) >= 2


def test_a_killed_worker_changes_nothing(client, city):
    expected = penumbra.Scene.load(city).sun_hours(date="2026-03-21", step="10min").to_json()
    result = {}

    def job():
        result["study"] = pd.sun_hours(city, date="2026-03-21", step="10min", client=client,
                                       tasks=26)

    running = threading.Thread(target=job)
    running.start()
    deadline = time.monotonic() + 60
    while not any(client.processing().values()) and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)  # tasks under way
    victim = next(iter(client.run(os.getpid).values()))
    os.kill(victim, signal.SIGKILL)
    assert running.is_alive()  # killed in the middle of the job, not after it
    running.join(timeout=300)
    assert not running.is_alive()
    assert result["study"].to_json() == expected
    client.wait_for_workers(2, timeout=60)
    assert victim not in client.run(os.getpid).values()  # the nanny started a new worker


def test_a_penumbra_error_fails_the_job_with_its_message(client, city):
    with pytest.raises(penumbra.InputError) as error:
        pd.sun_hours(city, date="2026-03-21", step="1h", client=client, light="moon")
    assert "moon" in str(error.value)
    bad = np.array([[0, 0, 0, 0, 0, 1.0], [0, 0, 0, 0, 0, 3.0]])
    with pytest.raises(penumbra.InputError) as normal:
        pd.illuminance(scene_path("office.json"), bad, client=client, tasks=2)
    assert "normal" in str(normal.value)


def run(*arguments, env=None):
    done = subprocess.run([BINARY, *map(str, arguments)], capture_output=True, text=True,
                          env=env)
    return done.returncode, done.stdout, done.stderr


def test_the_command_line_on_dask_writes_the_same_files(client, city, tmp_path):
    address = client.scheduler.address
    outputs = {}
    for mode, extra in (("local", []), ("dask", ["--dask", address])):
        d = tmp_path / mode
        d.mkdir()
        status, text, errors = run(
            "sun-hours", city, "--date", "2026-03-21", "--step", "1h", "-o", d / "h.json",
            "--report", d / "h.csv", "--svg", d / "h.svg", "--png", d / "h.png",
            "--threshold", "2h", "--region", "ground", *extra)
        assert status == 0, errors
        status, plane, errors = run(
            "illuminance", scene_path("office.json"), "--workplane", 0.8, "--spacing", 0.25,
            "-o", d / "wp.csv", "--svg", d / "wp.svg", *extra)
        assert status == 0, errors
        status, _, errors = run(
            "shadows", city, "--times", "2026-03-21T06:00,2026-03-21T18:00,2h", "--exact",
            "-o", d / "d.json", "--svg", d / "d.svg", "--receivers", "ground,building1*", *extra)
        assert status == 0, errors
        outputs[mode] = (text, plane, {f.name: f.read_bytes() for f in sorted(d.iterdir())})
    assert outputs["dask"] == outputs["local"]
    assert set(outputs["dask"][2]) == {"h.json", "h.csv", "h.svg", "h.png", "wp.csv", "wp.svg",
                                       "d.json", "d.svg"}


def test_the_command_line_on_dask_reports_bad_input(client, city, tmp_path):
    status, _, errors = run("sun-hours", city, "--date", "2026-03-21", "--light", "moon",
                            "--dask", client.scheduler.address, "-o", tmp_path / "h.json")
    assert status == 2 and "moon" in errors and not (tmp_path / "h.json").exists()
    env = dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s")
    status, _, errors = run("sun-hours", city, "--date", "2026-03-21", "--step", "1h",
                            "--dask", "tcp://127.0.0.1:9", "-o", tmp_path / "h.json", env=env)
    assert status == 2 and "--dask" in errors and not (tmp_path / "h.json").exists()


def test_awkward_names_merge_in_the_documents_order(client, city, tmp_path):
    # owners named with non-ASCII letters, commas, quotes and spaces: the merge sorts face
    # entries by the names' UTF-8 bytes, as the engine's std::string order does
    document = json.loads(city.read_text())
    names = ["Zürich, Bau 1", "école \"A\"", "ßtraße", "a,b", "Ωmega", "building 'x'",
             "日本", "Z", "z", "ä", "A b", "№7"]
    for obj, name in zip([o for o in document["objects"] if o["name"] != "ground"], names):
        obj["name"] = name
    awkward = tmp_path / "awkward city.json"
    awkward.write_text(json.dumps(document, ensure_ascii=False), encoding="utf-8")
    single = penumbra.Scene.load(awkward).sun_hours(date="2026-03-21", step="1h", exact=True)
    spread = pd.sun_hours(awkward, date="2026-03-21", step="1h", client=client, exact=True,
                          tasks=5)
    assert spread.to_json() == single.to_json()
    owners = [face["object"] for face in single.faces]
    assert set(names) <= set(owners)
    chosen = pd.sun_hours(awkward, date="2026-03-21", step="1h", client=client,
                          receivers=["日本", "a,b"])
    assert sorted({face["object"] for face in chosen.faces}) == ["a,b", "日本"]
