"""Shared fixtures of the Python module's tests: the source tree, the command-line tool (the
values the module must equal), and a small generated city with a sun for the studies."""

import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("PENUMBRA_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("PENUMBRA_BINARY", str(SOURCE / "build" / "penumbra"))


def scene_path(name):
    return SOURCE / "fixtures" / "scenes" / name


def run_cli(*arguments):
    """runs the command line; returns its standard output (raises on failure)."""
    done = subprocess.run([BINARY, *map(str, arguments)], capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError(f"penumbra {' '.join(map(str, arguments))}: {done.stderr}")
    return done.stdout


@pytest.fixture(scope="session")
def city(tmp_path_factory):
    """a 12-building city under the London sun of 21 March 2026 (scripts/city, fixed seed)."""
    path = tmp_path_factory.mktemp("city") / "city.json"
    text = subprocess.run([sys.executable, str(SOURCE / "scripts" / "city"), "12", "--sun-place",
                           "51.5,-0.12,2026-03-21T12:00:00+00:00"],
                          capture_output=True, text=True, check=True).stdout
    path.write_text(text)
    return path
