"""penumbra: exact shadows, illuminance and sun studies for polyhedral scenes.

A scene is loaded from a scene file (docs/scene-format.md) or a dict of the same form; paths
here are the repository's, as the tests run this example::

    >>> import penumbra, numpy as np
    >>> scene = penumbra.Scene.load("fixtures/scenes/linear-fig5.json")   # a block, a tube
    >>> shadows = scene.shadows()                  # exact, as `penumbra shadows --exact`
    >>> floor = shadows.face("floor", 3)           # the floor's top face
    >>> tube = floor.lights["tube"]
    >>> tube.umbra.polygons[0].exact_outer[1]      # exact rationals
    (Fraction(1, 3), Fraction(-1, 2), Fraction(0, 1))
    >>> tube.umbra.area, tube.penumbra.area        # m^2: 4/3 x 5/6 = 10/9, and 11 - 10/9
    (1.111111111111111, 9.888888888888888)
    >>> round(tube.penumbra.to_shapely().area, 9)  # shapely, in the face's frame
    9.888888889
    >>> points = np.array([[0, 0, 0, 0, 0, 1], [2, 2, 0, 0, 0, 1]], dtype=float)  # x, y, z, n
    >>> lux = scene.illuminance(points)            # lux, as `illuminance --points`
    >>> lux[0], bool(lux[1] > 0)                   # in the umbra; beyond the penumbra
    (0.0, True)

(The umbra is the rectangle [-1/2, 1/3] x [-1/2, 5/6] and the penumbra the rest of a hexagon of
area 11, derived by hand in tests/shadow/linear_figures_test.cpp, Nishita 1985 figure 5.)

Sun studies (``Scene.sun_hours``, ``solar_position``) and the distributed runs of
``penumbra.dask`` give what the command line gives, value for value. Bad input raises
``InputError`` (a ValueError) with the file and JSON path. The computations release the GIL.
See docs/python.md.
"""

import json
import os
from collections import namedtuple

import numpy as np

from . import _penumbra
from ._penumbra import InputError, format_json, solar_position
from ._shadows import FaceShadows, Frame, LightShadows, Polygon, PolygonSet, Shadows

__all__ = ["Scene", "Shadows", "FaceShadows", "LightShadows", "PolygonSet", "Polygon", "Frame",
           "SunHours", "Workplane", "Light", "InputError", "format_json", "solar_position"]

Light = namedtuple("Light", "name kind")
Light.__doc__ = "A light of a scene: its name and kind (point, linear or directional)."


def _study(date, step, to, light, site, utc_offset):
    """the arguments of a sun study, as the native functions take them."""
    return dict(date=date, step=step, to=to, light=light, site=site, utc_offset=utc_offset)


def _input_error(location, message, file=""):
    error = InputError(f"{file or '<input>'}: {location}: {message}")
    error.file, error.location, error.message = file, location, message
    return error


class Scene:
    """A scene (docs/scene-format.md), loaded once and queried many times."""

    def __init__(self, native):
        self._native = native

    @classmethod
    def load(cls, path):
        """loads the scene file at path (str or os.PathLike); raises InputError."""
        return cls(_penumbra.NativeScene.load(os.fspath(path)))

    @classmethod
    def from_dict(cls, document, base_dir=None, name="<dict>"):
        """builds the scene a dict of the scene format describes. Relative paths in it (meshes,
        photometric files) resolve in base_dir (default: the working directory); errors name
        the file as base_dir/name."""
        file = os.path.join(os.fspath(base_dir) if base_dir is not None else os.getcwd(), name)
        return cls(_penumbra.NativeScene.parse(json.dumps(document, allow_nan=True), file))

    @property
    def file(self):
        """the scene file (for a dict, the name errors give it)."""
        return self._native.file

    @property
    def objects(self):
        """the objects' names, in the scene's order (pieces of models as part#k)."""
        return self._native.objects

    @property
    def lights(self):
        """the lights (Light: name, kind), in the scene's order: the order of per-light
        columns."""
        return [Light(*light) for light in self._native.lights]

    @property
    def suns(self):
        """the names of the lights given by place and time."""
        return self._native.suns

    @property
    def warnings(self):
        """problems found while loading that did not stop it (e.g. unknown keys)."""
        return self._native.warnings

    def owners(self):
        """the owners of receiving faces (objects, and parts of models) in canonical order: a
        list of (name, receiving faces, (xmin, ymin, zmin, xmax, ymax, zmax))."""
        return self._native.owners()

    def shadow_document(self, light=None, receivers=None, exact=False, range_fraction=1 / 256,
                        full_scale_lux=500.0, range_lux=None):
        """returns (document, warnings): the JSON document of `penumbra shadows` as dicts and
        lists, equal value for value to the command's file read by json.load. receivers: a
        str of shell patterns as --receivers, or a list of exact owner names."""
        return self._native.shadow_document(light, receivers, exact, range_fraction,
                                            full_scale_lux, range_lux)

    def shadows(self, light=None, receivers=None, exact=True, **culling):
        """returns the exact shadows (Shadows) of every receiving face under every light (or
        the light named). exact=True keeps the exact rational coordinates (Fraction).
        culling: range_fraction, full_scale_lux, range_lux as `penumbra shadows`."""
        return Shadows(*self.shadow_document(light, receivers, exact, **culling))

    def illuminance(self, points, per_light=False, inside=False):
        """returns the illuminance (lux) at points, an (N, 6) array of x, y, z, nx, ny, nz
        (unit normals, within 1e-3, as `illuminance --points`): an (N,) float64 array, or
        with per_light a dict light name -> (N,) array (and "total"). inside=True also
        returns the name of the object holding each point ('' for none) as a list."""
        points = np.ascontiguousarray(points, dtype=np.float64)
        total, lights, holder = self._native.illuminance(points)
        result = total
        if per_light:
            result = {light.name: lights[:, k] for k, light in enumerate(self.lights)}
            result["total"] = total
        if inside:
            names = self.objects
            return result, [names[k] if k >= 0 else "" for k in holder]
        return result

    def workplane(self, height, spacing, region=None):
        """returns the illuminance on a horizontal work plane (Workplane) at height, cells no
        wider than spacing, over region (x0, y0, x1, y1; default the scene's plan bounds),
        as `penumbra illuminance --workplane`."""
        grid = self.workplane_grid(height, spacing, region)
        total, lights, holder = self._native.illuminance(grid[0])
        return Workplane(self, grid, total, lights, holder)

    def workplane_grid(self, height, spacing, region=None):
        """returns (points (N, 6), columns, rows, region): the cell centres of a work plane,
        row by row, with normal +z."""
        return self._native.workplane_grid(height, spacing,
                                           None if region is None else tuple(region))

    def sun_shadows(self, time, light=None, exact=True, receivers=None, range_fraction=1 / 256,
                    full_scale_lux=500.0, range_lux=None):
        """returns the shadows (Shadows) of the scene lit by its sun alone at time (ISO 8601;
        without an offset, on the clock of the sun's time): one time of `penumbra shadows
        --times`. Raises InputError when the sun is below the horizon then."""
        step = _penumbra.sun_step_at(self._native, light or "", time)
        if not step[6]:
            raise _input_error("time", f"the sun is below the horizon at {step[0]}")
        documents, warnings = _penumbra.sun_shadow_documents(
            self._native, light or "", [step[:6]], receivers, exact, range_fraction,
            full_scale_lux, range_lux)
        return Shadows(documents[0], warnings)

    def sun_hours(self, date=None, step="10min", to=None, light=None, site=None,
                  utc_offset=None, receivers=None, exact=False):
        """returns the sun-hours study (SunHours) of `penumbra sun-hours`: every face cut into
        parts by the time the sun reaches them, dates YYYY-MM-DD, step like "10min" or "1h",
        site "LAT,LON[,ELEV]" for a scene whose sun is a fixed direction."""
        arguments = _study(date, step, to, light, site, utc_offset)
        document, warnings = _penumbra.sun_hours_document(self._native, arguments, receivers,
                                                          exact)
        return SunHours(document, warnings)

    def sun_steps(self, date=None, step="10min", to=None, light=None, site=None,
                  utc_offset=None):
        """returns the steps of a sun study: a list of (time, azimuth_deg, elevation_deg, dx,
        dy, dz, up), (dx, dy, dz) the direction sunlight travels in the model frame."""
        return _penumbra.sun_steps(self._native, _study(date, step, to, light, site, utc_offset))

    def __repr__(self):
        return (f"Scene({self.file!r}: {len(self.objects)} objects, "
                f"{len(self.lights)} lights)")


class Workplane:
    """Illuminance on a work-plane grid: ``points`` (N, 6), ``values`` (N,) lux, ``per_light``
    (light name -> (N,)), ``inside`` (N,) object index or -1, ``columns``, ``rows``,
    ``region``; ``grid()`` the values as a (rows, columns) array; ``statistics()``."""

    def __init__(self, scene, grid, total, lights, holder):
        self.points, self.columns, self.rows, self.region = grid
        self.values = total
        self.per_light = {light.name: lights[:, k] for k, light in enumerate(scene.lights)}
        self.inside = holder

    def grid(self):
        """the values as a (rows, columns) array, row 0 at the smallest y."""
        return self.values.reshape(self.rows, self.columns)

    def statistics(self):
        """minimum, average, maximum and uniformity U0 = Emin / Eavg over the points not inside
        an object, as `penumbra illuminance --workplane` prints them."""
        counted = self.values[self.inside < 0]
        if counted.size == 0:
            return {"points": 0, "min": 0.0, "average": 0.0, "max": 0.0, "uniformity": 0.0}
        average = float(counted.mean())
        return {"points": int(counted.size), "min": float(counted.min()), "average": average,
                "max": float(counted.max()),
                "uniformity": float(counted.min()) / average if average > 0 else 0.0}


class SunHours:
    """A sun-hours study: ``document`` (the JSON of `penumbra sun-hours`), ``faces`` (its face
    entries, each with "hours": parts with area, minutes and polygons), ``warnings``;
    ``to_json()`` gives the command's file byte for byte; ``write_svg`` and ``write_png`` the
    heat maps."""

    def __init__(self, document, warnings=()):
        self.document = document
        self.warnings = list(warnings)

    @property
    def faces(self):
        return self.document["faces"]

    @property
    def longest_minutes(self):
        return self.document["longest_minutes"]

    def to_json(self):
        return format_json(self.document)

    def write_json(self, path):
        with open(path, "w", encoding="utf-8") as out:
            out.write(self.to_json())

    def write_svg(self, path, view="top"):
        _penumbra.write_sun_hours_svg(self.document, os.fspath(path), view)

    def write_png(self, path, width=1200):
        _penumbra.write_sun_hours_png(self.document, os.fspath(path), width)

    def __repr__(self):
        return f"SunHours({len(self.faces)} faces, longest {self.longest_minutes} min)"
