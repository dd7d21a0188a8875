"""penumbra's large jobs on a Dask cluster (docs/python.md, "Dask").

A job is split into tasks, the tasks run on the workers of a ``dask.distributed.Client`` (a
``LocalCluster`` on this machine when no client or scheduler address is given), and the
results are merged into exactly what the single-process run gives:

- ``sun_hours``: by receiving faces, in spatial tiles of the objects that own them (every face
  of an object, and every piece of a model's part, in one tile; the others still cast
  shadows), merged in the documents' canonical order;
- ``illuminance`` and ``workplane``: by chunks of points, concatenated;
- ``shadow_times``: by time steps, a few a task, as ``shadows --times``.

Each worker loads a scene once (the path is the key: the workers must see the scene file, and
what it refers to, at the same path: a shared file system or a copy) and keeps it for the
tasks that follow. Dask retries a task whose worker died (``retries``); a task that raises a
penumbra error fails the job with that error (``InputError``), which is not retried.
"""

import contextlib
import math
import os
import threading

import numpy as np

from . import InputError, Scene, SunHours, Workplane, _input_error, _penumbra

__all__ = ["sun_hours", "illuminance", "workplane", "shadow_times", "spatial_tiles",
           "client_for", "worker_loads"]

# === On the workers

_scenes = {}
_scenes_lock = threading.Lock()
_loads = 0


def _scene(path):
    """returns the scene at path, loaded once in this process."""
    global _loads
    with _scenes_lock:
        scene = _scenes.get(path)
        if scene is None:
            scene = _scenes[path] = Scene.load(path)
            _loads += 1
        return scene


def worker_loads():
    """the number of scenes this process has loaded (run on workers with client.run)."""
    return _loads


class _Refused:
    """A penumbra error a task met: returned rather than raised, so that Dask does not retry
    a task whose input is bad; the client raises it."""

    def __init__(self, error):
        self.error = error


def _task(work):
    def run(*arguments):
        try:
            return work(*arguments)
        except InputError as error:
            return _Refused(error)

    run.__name__ = work.__name__
    return run


def _sun_hours_tile(path, owners, study, exact):
    result = _scene(path).sun_hours(receivers=list(owners), exact=exact, **study)
    return result.document, result.warnings


def _illuminance_chunk(path, points):
    return _scene(path)._native.illuminance(np.ascontiguousarray(points, dtype=np.float64))


def _shadow_times_chunk(path, light, steps, receivers, exact, culling):
    return _penumbra.sun_shadow_documents(_scene(path)._native, light, steps, receivers, exact,
                                          culling.get("range_fraction", 1 / 256),
                                          culling.get("full_scale_lux", 500.0),
                                          culling.get("range_lux"))


def _gather(client, work, *arguments, retries):
    """runs work over the zipped arguments on client; returns the results in order."""
    futures = client.map(_task(work), *arguments, retries=retries, pure=False)
    results = client.gather(futures)
    for result in results:
        if isinstance(result, _Refused):
            raise result.error
    return results


# === On the client


@contextlib.contextmanager
def client_for(client=None, workers=2, threads_per_worker=1):
    """yields a Client: client itself; a Client connected to client when it is a scheduler
    address ("tcp://host:8786"); otherwise a LocalCluster of workers processes on loopback,
    closed afterwards."""
    from distributed import Client, LocalCluster

    if client is not None and not isinstance(client, str):
        yield client
        return
    if isinstance(client, str):
        with Client(client) as connected:
            yield connected
        return
    with LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker, processes=True,
                      host="127.0.0.1", dashboard_address=None) as cluster, \
            Client(cluster) as local:
        yield local


def _cores(client):
    return max(1, sum(client.nthreads().values()))


def spatial_tiles(owners, count):
    """returns count (or fewer) lists of owner names: the owners (name, faces, box) ordered
    along a grid of plan cells (row by row, back and forth, so that neighbours share a tile)
    and cut into runs of about equal numbers of faces; the tile holding the owner of largest
    plan extent first (a ground under a city costs more than its few faces say, and starting
    it first shortens the job)."""
    if not owners:
        return []
    centres = [((box[0] + box[3]) / 2, (box[1] + box[4]) / 2) for _, _, box in owners]
    x0, y0 = min(c[0] for c in centres), min(c[1] for c in centres)
    side = max(1, math.ceil(math.sqrt(count)))
    width = (max(c[0] for c in centres) - x0) / side or 1.0
    depth = (max(c[1] for c in centres) - y0) / side or 1.0

    def cell(k):
        column = min(side - 1, int((centres[k][0] - x0) / width))
        row = min(side - 1, int((centres[k][1] - y0) / depth))
        return (row, column if row % 2 == 0 else side - 1 - column, owners[k][0])

    def extent(k):
        box = owners[k][2]
        return (box[3] - box[0]) * (box[4] - box[1])

    order = sorted(range(len(owners)), key=cell)
    total = sum(max(1, owners[k][1]) for k in order)
    tiles, current, weight = [], [], 0
    for k in order:
        current.append(k)
        weight += max(1, owners[k][1])
        if weight >= total * (len(tiles) + 1) / count and len(tiles) < count - 1:
            tiles.append(current)
            current = []
    if current:
        tiles.append(current)
    tiles.sort(key=lambda tile: -max(extent(k) for k in tile))
    return [[owners[k][0] for k in tile] for tile in tiles]


def _canonical(entry):
    # the documents' order: the owner's name as bytes (std::string compares so), then the face
    return (entry["object"].encode("utf-8"), entry["face"])


def merge_sun_hours(documents):
    """returns the sun-hours document of the whole scene from those of disjoint tiles."""
    merged = dict(documents[0])
    merged["faces"] = sorted((face for d in documents for face in d["faces"]), key=_canonical)
    merged["longest_minutes"] = max(d["longest_minutes"] for d in documents)
    return merged


def sun_hours(scene_path, date=None, step="10min", client=None, tasks=None, retries=2,
              exact=False, **study):
    """returns the sun-hours study (SunHours) of the scene file, equal to
    Scene.load(scene_path).sun_hours(date, step, exact=exact, **study) and to `penumbra
    sun-hours`: tasks (default four per worker thread) of spatial tiles of receiving faces.
    study: to, light, site, utc_offset, receivers (the faces asked for: a list of owners)."""
    path = os.path.abspath(os.fspath(scene_path))
    scene = Scene.load(path)
    chosen = study.pop("receivers", None)
    owners = scene.owners()
    if chosen is not None:
        names = set(chosen)
        missing = names - {o[0] for o in owners}
        if missing:
            raise _input_error("receivers", f"no object or part named '{sorted(missing)[0]}'",
                               scene.file)
        owners = [o for o in owners if o[0] in names]
    study = dict(study, date=date, step=step)
    scene.sun_steps(**study)  # bad dates, steps and suns fail here, before any task
    if not owners:  # nothing receives: the (empty) study of one process
        return scene.sun_hours(exact=exact, receivers=chosen, **study)
    with client_for(client) as running:
        tiles = spatial_tiles(owners, tasks or 4 * _cores(running))
        parts = _gather(running, _sun_hours_tile, [path] * len(tiles), tiles,
                        [study] * len(tiles), [exact] * len(tiles), retries=retries)
    warnings = []
    for _, found in parts:
        warnings += [w for w in found if w not in warnings]
    return SunHours(merge_sun_hours([document for document, _ in parts]), warnings)


def _chunks(count, tasks):
    size = max(1, math.ceil(count / max(1, tasks)))
    return [(start, min(count, start + size)) for start in range(0, count, size)]


def _illuminance_arrays(path, points, client, tasks, retries):
    with client_for(client) as running:
        chunks = _chunks(len(points), tasks or 4 * _cores(running))
        parts = _gather(running, _illuminance_chunk, [path] * len(chunks),
                        [points[a:b] for a, b in chunks], retries=retries)
    if not parts:
        return np.zeros(0), np.zeros((0, 0)), np.zeros(0, dtype=np.int64)
    return tuple(np.concatenate([part[k] for part in parts]) for k in range(3))


def illuminance(scene_path, points, client=None, per_light=False, tasks=None, retries=2):
    """returns Scene.load(scene_path).illuminance(points, per_light), computed in chunks of
    points on the cluster."""
    path = os.path.abspath(os.fspath(scene_path))
    scene = Scene.load(path)
    points = np.ascontiguousarray(points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 6:
        raise InputError("points: expected an (N, 6) array of x, y, z, nx, ny, nz")
    total, lights, _ = _illuminance_arrays(path, points, client, tasks, retries)
    if not per_light:
        return total
    result = {light.name: lights[:, k] for k, light in enumerate(scene.lights)}
    result["total"] = total
    return result


def workplane(scene_path, height, spacing, region=None, client=None, tasks=None, retries=2):
    """returns Scene.load(scene_path).workplane(height, spacing, region) (Workplane),
    computed in chunks of grid points on the cluster."""
    path = os.path.abspath(os.fspath(scene_path))
    scene = Scene.load(path)
    grid = scene.workplane_grid(height, spacing, region)
    return Workplane(scene, grid, *_illuminance_arrays(path, grid[0], client, tasks, retries))


def shadow_times(scene_path, steps, light="", client=None, receivers=None, exact=False,
                 tasks=None, retries=2, **culling):
    """returns (documents, warnings): the shadow document of the scene lit by its sun alone
    from each step (time, azimuth_deg, elevation_deg, dx, dy, dz), the times of `penumbra
    shadows --times` (which computes the steps), a few steps a task."""
    path = os.path.abspath(os.fspath(scene_path))
    steps = [tuple(step) for step in steps]
    with client_for(client) as running:
        chunks = _chunks(len(steps), tasks or 2 * _cores(running))
        parts = _gather(running, _shadow_times_chunk, [path] * len(chunks),
                        [light] * len(chunks), [steps[a:b] for a, b in chunks],
                        [receivers] * len(chunks), [exact] * len(chunks),
                        [culling] * len(chunks), retries=retries)
    documents, warnings = [], []
    for found, said in parts:
        documents += found
        warnings += [w for w in said if w not in warnings]
    return documents, warnings
