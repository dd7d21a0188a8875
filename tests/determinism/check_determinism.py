#!/usr/bin/env python3
"""Every verb's outputs are byte-identical across runs, across thread counts (PENUMBRA_THREADS=1
against the default) and across the order of the objects in the scene (issue #22: documents,
drawings, tables, images and basis files). Each case runs four times: twice as given, once on
one thread, once with the scene's objects listed in reverse (a copy under the same name in a
tree whose other folders link to fixtures/, so that relative paths resolve and the scene reads
the same in every output); every file written and the standard output must be the same bytes
each time. Reports of the time a stage took go to standard error, which is not compared.

Usage: check_determinism.py SOURCE_DIR PENUMBRA_BINARY [CASE...]. Exit status 0 when every
case agrees."""

import json
import os
import pathlib
import struct
import subprocess
import sys
import tempfile

source = pathlib.Path(sys.argv[1]).resolve()
binary = os.path.abspath(sys.argv[2])
scenes = source / "fixtures" / "scenes"

# name: (scene, arguments; {o} is the run's output directory, {s} the scene file)
CASES = {
    "info": ("office.json", ["info", "{s}"]),
    "shadows": ("office.json", ["shadows", "{s}", "--exact", "-o", "{o}/a.json", "--svg",
                                "{o}/a.svg", "--loops", "--dxf", "{o}/a.dxf", "--report",
                                "{o}/a.csv"]),
    "shadows-model": ("mesh-courtyard.json", ["shadows", "{s}", "--exact", "-o", "{o}/a.json",
                                              "--svg", "{o}/a.svg", "--view", "faces", "--dxf",
                                              "{o}/a.dxf"]),
    "shadows-times": ("sun-london.json", ["shadows", "{s}", "--times",
                                          "2026-03-21T08:00,2026-03-21T16:00,2h", "-o",
                                          "{o}/d.json", "--svg", "{o}/d.svg"]),
    "check": ("office.json", ["check", "{s}", "--golden", "../golden/office.json"]),
    "render": ("office.json", ["render", "{s}", "-o", "{o}/r.png", "--isolux", "--width", "160",
                               "--height", "120", "--values", "{o}/r.csv"]),
    # without indirect light: see docs/reliability.md, "Determinism" (touching tiles)
    "raytrace": ("whitted-fig7.json", ["raytrace", "{s}", "-o", "{o}/t.png", "--values",
                                       "{o}/t.csv", "--indirect", "off"]),
    "illuminance": ("office.json", ["illuminance", "{s}", "--workplane", "0.75", "--spacing",
                                    "0.25", "-o", "{o}/w.csv", "--svg", "{o}/w.svg"]),
    "radiosity": ("basis-room.json", ["radiosity", "{s}", "--patch-size", "0.5", "-o",
                                      "{o}/p.csv"]),
    "basis": ("basis-room.json", ["basis", "{s}", "--degree", "3", "--patch-size", "0.5", "-o",
                                  "{o}/b.pbl"]),
    "relight": ("basis-room.json", [["basis", "{s}", "--degree", "3", "--patch-size", "0.5", "-o",
                                     "{o}/b.pbl"],
                                    ["relight", "{o}/b.pbl", "--scale", "centre=0.5", "-o",
                                     "{o}/relit.png"],
                                    ["relight", "{o}/b.pbl", "--scale", "centre=0.5",
                                     "--patches", "{o}/relit.csv"]]),
    "sun": ("sun-london.json", ["sun", "{s}", "--step", "1h", "-o", "{o}/s.csv"]),
    "sun-hours": ("sun-london.json", ["sun-hours", "{s}", "--date", "2026-03-21", "--step", "1h",
                                      "--exact", "-o", "{o}/h.json", "--report", "{o}/h.csv",
                                      "--svg", "{o}/h.svg", "--png", "{o}/h.png", "--threshold",
                                      "2h", "--region", "ground"]),
    "lid": (None, ["lid", "fit", '{"cos_power": 10, "spread_deg": 90, "candela": 800}',
                   "--degree", "6", "--sigma"]),
}


def comparable(name, data, scene_dir):
    """returns a file's bytes as compared: a basis file records the absolute directory that its
    lights' photometric files are relative to (the reversed scenes live elsewhere), so in its
    header that directory is replaced by a mark; every other file as it is."""
    if not name.endswith(".pbl"):
        return data
    length = struct.unpack("<Q", data[8:16])[0]
    header = json.loads(data[16:16 + length])
    for light in header.get("lights", []):
        if light.get("lid_base") == str(scene_dir):
            light["lid_base"] = "SCENES"
    return data[:8] + json.dumps(header, sort_keys=True).encode() + data[16 + length:]


def reversed_tree(top):
    """returns a fixtures tree under top whose scenes list their objects in reverse: scenes/
    holds the reversed copies under their own names, every other folder of fixtures/ is linked,
    so that relative paths resolve and a scene's name reads the same in every output."""
    tree = top / "fixtures"
    (tree / "scenes").mkdir(parents=True)
    for entry in (source / "fixtures").iterdir():
        if entry.name != "scenes":
            (tree / entry.name).symlink_to(entry)
    for scene in scenes.glob("*.json"):
        document = json.loads(scene.read_text())
        document["objects"] = document.get("objects", [])[::-1]
        (tree / "scenes" / scene.name).write_text(json.dumps(document))
    return tree / "scenes"


def run(arguments, scene_dir, scene_name, out, threads):
    """runs the case's command (or commands, one after the other) in scene_dir, the scene named
    by its bare name; returns the exit status, standard output and files."""
    out.mkdir()
    env = dict(os.environ)
    env.pop("PENUMBRA_THREADS", None)
    if threads:
        env["PENUMBRA_THREADS"] = threads
    commands = arguments if isinstance(arguments[0], list) else [arguments]
    status, text = 0, b""
    for command in commands:
        words = [w.replace("{o}", str(out)).replace("{s}", scene_name) for w in command]
        done = subprocess.run([binary, *words], capture_output=True, env=env, cwd=scene_dir)
        status, text = status or done.returncode, text + done.stdout
    files = {p.name: comparable(p.name, p.read_bytes(), scene_dir) for p in sorted(out.iterdir())}
    # the report names the files written: each run writes into a folder of its own
    return status, text.replace(str(out).encode(), b"OUT"), files


def check(name, work, reversed_scenes):
    scene_name, arguments = CASES[name]
    scene_name = scene_name or "none"
    runs = {"as given": run(arguments, scenes, scene_name, work / "a", None),
            "again": run(arguments, scenes, scene_name, work / "b", None),
            "PENUMBRA_THREADS=1": run(arguments, scenes, scene_name, work / "c", "1"),
            "objects reversed": run(arguments, reversed_scenes, scene_name, work / "d", None)}
    status, text, files = runs["as given"]
    problems = []
    if status != 0:
        problems.append(f"exit status {status}")
    if not files and not text:
        problems.append("no output")
    for label, (other_status, other_text, other_files) in runs.items():
        if other_status != status:
            problems.append(f"{label}: exit status {other_status} against {status}")
        if other_text != text:
            problems.append(f"{label}: the standard output differs")
        for file in sorted(set(files) | set(other_files)):
            if files.get(file) != other_files.get(file):
                problems.append(f"{label}: {file} differs")
    return problems


def main():
    names = sys.argv[3:] or list(CASES)
    failed = 0
    with tempfile.TemporaryDirectory(prefix="penumbra-determinism-") as top:
        reversed_scenes = reversed_tree(pathlib.Path(top))
        for name in names:
            work = pathlib.Path(top) / name
            work.mkdir()
            problems = check(name, work, reversed_scenes)
            print(f"{name}: {'same bytes in 4 runs' if not problems else '; '.join(problems)}")
            failed += bool(problems)
    print(f"{len(names)} cases, {failed} differing")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
