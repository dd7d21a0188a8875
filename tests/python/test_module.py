"""import penumbra against the command line: the same documents value for value (exact
rationals equal, doubles bitwise), the same illuminance, the errors as exceptions."""

import contextlib
import doctest
import csv
import io
import json
import os
import subprocess
import threading
import time
from fractions import Fraction

import numpy as np
import pytest

import penumbra
from conftest import BINARY, SOURCE, run_cli, scene_path

SHADOW_SCENES = ["linear-fig5.json", "mesh-courtyard.json", "shadow-cube-point.json",
                 "every-kind.json", "mesh-window.json"]


@pytest.mark.parametrize("name", SHADOW_SCENES)
def test_shadow_document_is_the_command_lines(name, tmp_path):
    out = tmp_path / "shadows.json"
    run_cli("shadows", scene_path(name), "--exact", "-o", out)
    document, _ = penumbra.Scene.load(scene_path(name)).shadow_document(exact=True)
    text = out.read_text()
    assert document == json.loads(text)  # floats compare bitwise (no NaN in documents)
    assert penumbra.format_json(document) == text  # byte for byte


def exact_rings(shadows):
    for face in shadows:
        yield face.boundary
        for light in face.lights.values():
            for polygons in (light.shadow, light.umbra, light.penumbra, light.lit):
                yield from polygons


def test_fractions_round_trip_and_match_the_doubles():
    shadows = penumbra.Scene.load(scene_path("linear-fig5.json")).shadows()
    document = shadows.document
    texts = [c for f in document["faces"] for ring in f["exact"]["boundary"] for c in ring]
    assert texts and all(str(Fraction(t)) == t for t in texts)  # canonical p/q both ways
    count = 0
    for polygon in exact_rings(shadows):
        for exact, rounded in zip(polygon.exact_outer, polygon.outer):
            assert all(isinstance(c, Fraction) for c in exact)
            # the doubles are the exact values rounded (CGAL's to_double: within one ulp, not
            # always the nearest double: 5/6 comes out one below)
            for c, d in zip(exact, rounded):
                assert abs(Fraction(float(d)) - c) < Fraction(np.spacing(abs(float(d))))
            count += 1
    assert count > 20


def test_numpy_types_and_shapely_areas():
    pytest.importorskip("shapely")
    shadows = penumbra.Scene.load(scene_path("mesh-courtyard.json")).shadows()
    checked = 0
    for face in shadows:
        assert face.plane.dtype == np.float64 and face.plane.shape == (4,)
        assert face.boundary.outer.dtype == np.float64 and face.boundary.outer.shape[1] == 3
        for light in face.lights.values():
            for polygons in (light.shadow, light.lit):
                if not len(polygons):
                    continue
                # GEOS's area of the frame polygons against the exact area of the document
                assert polygons.to_shapely().area == pytest.approx(polygons.area, rel=1e-9)
                checked += 1
    assert checked > 5


def points_csv(path, points):
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["x", "y", "z", "nx", "ny", "nz"])
        writer.writerows([repr(float(v)) for v in row] for row in points)


def random_points(count, seed, box):
    rng = np.random.default_rng(seed)
    points = np.empty((count, 6))
    for axis in range(3):
        points[:, axis] = rng.uniform(box[0][axis], box[1][axis], count)
    normals = rng.normal(size=(count, 3))
    points[:, 3:] = normals / np.linalg.norm(normals, axis=1)[:, None]
    return points


def read_values(text):
    rows = list(csv.DictReader(io.StringIO(text)))
    return rows


def test_illuminance_equals_the_command_line(tmp_path):
    name = scene_path("every-kind.json")
    points = random_points(300, 7, ((-4, -4, 0), (4, 4, 3)))
    points_csv(tmp_path / "points.csv", points)
    rows = read_values(run_cli("illuminance", name, "--points", tmp_path / "points.csv"))
    scene = penumbra.Scene.load(name)
    values = scene.illuminance(points)
    assert values.dtype == np.float64 and values.shape == (300,)
    assert np.array_equal(values, np.array([float(r["E"]) for r in rows]))
    per_light, inside = scene.illuminance(points, per_light=True, inside=True)
    assert set(per_light) == {light.name for light in scene.lights} | {"total"}
    for light in scene.lights:
        column = np.array([float(r[f"E[{light.name}]"]) for r in rows])
        assert per_light[light.name].shape == (300,)
        assert np.array_equal(per_light[light.name], column)
    assert inside == [r["inside"] for r in rows]
    assert any(inside) and sum(values > 0) > 100  # the sample meets both cases


def test_workplane_equals_the_command_line(tmp_path):
    name = scene_path("office.json")
    run_cli("illuminance", name, "--workplane", 0.8, "--spacing", 0.5, "-o", tmp_path / "wp.csv")
    rows = read_values((tmp_path / "wp.csv").read_text())
    plane = penumbra.Scene.load(name).workplane(0.8, 0.5)
    assert plane.points.shape == (len(rows), 6) and plane.grid().shape == (plane.rows, plane.columns)
    assert np.array_equal(plane.points[:, 0], [float(r["x"]) for r in rows])
    assert np.array_equal(plane.points[:, 1], [float(r["y"]) for r in rows])
    assert np.array_equal(plane.values, [float(r["E"]) for r in rows])


def test_sun_hours_and_sun_steps_equal_the_command_line(city, tmp_path):
    out = tmp_path / "hours.json"
    run_cli("sun-hours", city, "--date", "2026-03-21", "--step", "1h", "--exact", "-o", out)
    study = penumbra.Scene.load(city).sun_hours(date="2026-03-21", step="1h", exact=True)
    assert study.to_json() == out.read_text()
    rows = list(csv.DictReader(io.StringIO(run_cli("sun", city, "--step", "1h"))))
    steps = penumbra.Scene.load(city).sun_steps(date="2026-03-21", step="1h")
    # `penumbra sun` lists the closing midnight too; a study's steps stop before it
    assert len(rows) == len(steps) + 1
    rows = rows[:-1]
    assert [s[0] for s in steps] == [r["time"] for r in rows]
    assert [s[1:6] for s in steps] == [tuple(float(r[k]) for k in ("azimuth_deg",
                                       "elevation_deg", "dx", "dy", "dz")) for r in rows]
    # the full ERFA computation against the interpolating solver of studies (docs/sun.md:
    # within 1e-5 degrees)
    for row in rows:
        azimuth, elevation = penumbra.solar_position(51.5, -0.12, row["time"])
        assert abs(azimuth - float(row["azimuth_deg"])) < 1e-5
        assert abs(elevation - float(row["elevation_deg"])) < 1e-5


def test_sun_shadows_are_a_time_of_the_shadow_diagram(city, tmp_path):
    out = tmp_path / "diagram.json"
    run_cli("shadows", city, "--times", "2026-03-21T10:00,2026-03-21T15:30", "--exact", "-o", out)
    diagram = json.loads(out.read_text())
    scene = penumbra.Scene.load(city)
    for entry in diagram["times"]:
        shadows = scene.sun_shadows(entry["time"])
        assert shadows.document == entry["shadows"]
        assert len(shadows.faces) == len(scene.objects) * 6
    with pytest.raises(penumbra.InputError) as night:
        scene.sun_shadows("2026-03-21T23:00")
    assert night.value.location == "time" and "below the horizon" in night.value.message


def test_scene_from_dict_equals_the_file():
    path = scene_path("linear-fig5.json")
    from_file = penumbra.Scene.load(path).shadow_document(exact=True)[0]
    from_dict = penumbra.Scene.from_dict(json.loads(path.read_text()), base_dir=path.parent)
    assert from_dict.shadow_document(exact=True)[0] == from_file


def test_bad_input_raises_input_error_with_file_and_path(tmp_path):
    with pytest.raises(penumbra.InputError) as missing:
        penumbra.Scene.load(tmp_path / "nowhere.json")
    assert missing.value.file.endswith("nowhere.json")
    assert isinstance(missing.value, ValueError)
    document = json.loads(scene_path("linear-fig5.json").read_text())
    document["objects"][0]["convex"] = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]  # flat: not a solid
    with pytest.raises(penumbra.InputError) as flat:
        penumbra.Scene.from_dict(document, base_dir=tmp_path, name="mine.json")
    assert flat.value.file == str(tmp_path / "mine.json")
    assert flat.value.location.startswith("objects[0]")
    scene = penumbra.Scene.load(scene_path("every-kind.json"))
    with pytest.raises(penumbra.InputError) as shape:
        scene.illuminance(np.zeros((3, 5)))
    assert shape.value.location == "points"
    with pytest.raises(penumbra.InputError) as normal:
        scene.illuminance(np.array([[0, 0, 0, 0, 0, 1], [0, 0, 0, 0, 0, 2.0]]))
    assert normal.value.location == "points[1], columns nx,ny,nz"
    with pytest.raises(penumbra.InputError) as light:
        scene.shadows(light="nobody")
    assert "nobody" in light.value.message
    with pytest.raises(penumbra.InputError) as date:
        penumbra.Scene.load(scene_path("sun-london.json")).sun_hours(date="2026-02-30")
    assert date.value.location == "--date"


def ticks_while(work):
    """returns (ticks a Python thread counted while work ran, seconds work took)."""
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1

    counter = threading.Thread(target=count)
    counter.start()
    started = time.perf_counter()
    try:
        work()
    finally:
        seconds = time.perf_counter() - started
        done.set()
        counter.join()
    return ticks, seconds


def test_long_calls_release_the_gil(city):
    scene = penumbra.Scene.load(city)
    alone, idle = ticks_while(lambda: time.sleep(0.2))  # time.sleep releases the GIL
    rate = alone / idle
    ticks, seconds = ticks_while(lambda: scene.sun_hours(date="2026-03-21", step="20min"))
    assert seconds > 0.2
    # Held, the GIL would let the counter run one switch interval (5 ms) at most: 2 % of the
    # study; released, the counter shares the cores with the study's threads throughout.
    assert ticks > 0.1 * rate * seconds


def test_the_module_example_runs(monkeypatch):
    monkeypatch.chdir(SOURCE)  # the example's paths are the repository's
    failed, attempted = doctest.testmod(penumbra, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert attempted >= 8 and failed == 0


def test_help_documents_the_api():
    text = penumbra.__doc__ + penumbra.Scene.shadows.__doc__ + penumbra.Scene.illuminance.__doc__
    assert "InputError" in text and "(N, 6)" in text
    assert penumbra.InputError.__doc__ and "location" in penumbra.InputError.__doc__


def threads_and_output(arguments, threads):
    """runs the command line with PENUMBRA_THREADS=threads (unset for None); returns the most
    threads its process had at once (sampled every 10 ms) and its output."""
    env = dict(os.environ)
    env.pop("PENUMBRA_THREADS", None)
    if threads:
        env["PENUMBRA_THREADS"] = threads
    process = subprocess.Popen([BINARY, *map(str, arguments)], env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL)
    most = 0
    output = []
    reader = threading.Thread(target=lambda: output.append(process.stdout.read()))
    reader.start()
    while process.poll() is None:
        with contextlib.suppress(OSError):
            with open(f"/proc/{process.pid}/status") as status:
                for line in status:
                    if line.startswith("Threads:"):
                        most = max(most, int(line.split()[1]))
        time.sleep(0.01)
    reader.join()
    assert process.returncode == 0
    return most, output[0]


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="needs /proc")
def test_penumbra_threads_caps_the_loops_and_changes_nothing(city):
    arguments = ["sun-hours", city, "--date", "2026-03-21", "--step", "20min", "--exact"]
    one, text_one = threads_and_output(arguments, "1")
    default, text_default = threads_and_output(arguments, None)
    assert text_one == text_default
    assert one == 1  # TBB started no worker thread
    if (os.cpu_count() or 1) > 1:
        assert default > 1
