"""Shadows as Python objects: the shadow document of ``penumbra shadows`` (DESIGN.md, "Shadow
loops output") read into faces, lights and polygon sets, with exact coordinates as
``fractions.Fraction``, doubles as NumPy arrays and ``to_shapely()`` in each face's frame."""

from fractions import Fraction

import numpy as np


def _points(ring):
    return np.array(ring, dtype=np.float64).reshape(-1, 3)


def _fractions(ring):
    return [tuple(Fraction(c) for c in point) for point in ring]


class Frame:
    """A face's 2D frame: ``origin`` and the unit axes ``u``, ``v`` (NumPy, world metres).
    ``u x v`` points along the outward normal, so counter-clockwise in the frame is
    counter-clockwise seen from outside."""

    def __init__(self, entry):
        self.origin = np.array(entry["origin"], dtype=np.float64)
        self.u = np.array(entry["u"], dtype=np.float64)
        self.v = np.array(entry["v"], dtype=np.float64)

    def to_frame(self, points):
        """returns the (N, 2) frame coordinates (metres along u and v) of (N, 3) world points
        of the face's plane."""
        d = np.asarray(points, dtype=np.float64) - self.origin
        return np.stack([d @ self.u, d @ self.v], axis=-1)

    def __repr__(self):
        return f"Frame(origin={self.origin.tolist()}, u={self.u.tolist()}, v={self.v.tolist()})"


class Polygon:
    """A polygon with holes on a face: ``outer`` (N, 3) counter-clockwise seen from outside,
    ``holes`` clockwise, world coordinates as doubles. ``exact_outer`` and ``exact_holes``
    hold the exact rational coordinates (tuples of Fraction) when the document has them
    (``exact=True``), else None."""

    def __init__(self, outer, holes, exact, frame):
        self.outer = _points(outer)
        self.holes = [_points(h) for h in holes]
        self.exact_outer = _fractions(exact["outer"]) if exact is not None else None
        self.exact_holes = [_fractions(h) for h in exact["holes"]] if exact is not None else None
        self.frame = frame

    def to_shapely(self):
        """returns the polygon in the face's frame as a shapely Polygon (metres along u, v)."""
        from shapely.geometry import Polygon as ShapelyPolygon

        return ShapelyPolygon(self.frame.to_frame(self.outer),
                              [self.frame.to_frame(h) for h in self.holes])

    def __repr__(self):
        return f"Polygon({len(self.outer)} vertices, {len(self.holes)} holes)"


class PolygonSet:
    """A set of polygons on a face (shadow, umbra, penumbra or lit): ``area`` in m^2 (from the
    exact area) and ``polygons``."""

    def __init__(self, entry, frame):
        self.area = entry["area"]
        self.polygons = [Polygon(p["outer"], p["holes"], p.get("exact"), frame)
                         for p in entry["polygons"]]

    def __iter__(self):
        return iter(self.polygons)

    def __len__(self):
        return len(self.polygons)

    def to_shapely(self):
        """returns the set in the face's frame as a shapely MultiPolygon."""
        from shapely.geometry import MultiPolygon

        return MultiPolygon([p.to_shapely() for p in self.polygons])

    def __repr__(self):
        return f"PolygonSet(area={self.area}, {len(self.polygons)} polygons)"


class LightShadows:
    """What one light does to one face: ``shadow``, ``umbra``, ``penumbra`` and ``lit``
    (PolygonSet; for point and directional sources umbra == shadow and the penumbra is
    empty), ``faces_away``, ``joint_occlusion``, ``source_clipped``, and ``occluders`` (the
    document's entries: each occluder's own shadow polygon, and for tubes its loops)."""

    def __init__(self, entry, frame):
        self.light = entry["light"]
        self.shadow = PolygonSet(entry["shadow"], frame)
        self.umbra = PolygonSet(entry["umbra"], frame)
        self.penumbra = PolygonSet(entry["penumbra"], frame)
        self.lit = PolygonSet(entry["lit"], frame)
        self.faces_away = entry["faces_away"]
        self.joint_occlusion = entry.get("joint_occlusion", False)
        self.source_clipped = entry.get("source_clipped", False)
        self.occluders = entry["occluders"]

    def __repr__(self):
        return (f"LightShadows({self.light!r}, shadow {self.shadow.area} m2, "
                f"penumbra {self.penumbra.area} m2)")


class FaceShadows:
    """One receiving face: its ``object`` (the object, or the part of a mesh model) and
    ``face`` number, ``plane`` (a, b, c, d with a x + b y + c z + d = 0, outward normal
    (a, b, c)), ``frame``, ``boundary`` (Polygon), ``area`` (m^2) and ``lights`` (light name
    -> LightShadows). ``exact_plane`` holds Fractions when the document is exact."""

    def __init__(self, entry):
        self.object = entry["object"]
        self.face = entry["face"]
        self.plane = np.array(entry["plane"], dtype=np.float64)
        self.frame = Frame(entry["frame"])
        self.area = entry["area"]
        exact = entry.get("exact")
        self.exact_plane = tuple(Fraction(c) for c in exact["plane"]) if exact else None
        boundary = entry["boundary"]
        exact_boundary = exact["boundary"] if exact else None
        if isinstance(boundary, dict):  # a face of a mesh part: outer ring and holes
            self.boundary = Polygon(boundary["outer"], boundary["holes"], exact_boundary, self.frame)
        else:
            self.boundary = Polygon(boundary, [], {"outer": exact_boundary, "holes": []}
                                    if exact else None, self.frame)
        self.lights = {light["light"]: LightShadows(light, self.frame)
                       for light in entry.get("lights", [])}

    def __repr__(self):
        return f"FaceShadows({self.object!r}, face {self.face}, {len(self.lights)} lights)"


class Shadows:
    """The exact shadows of a scene: ``faces`` (FaceShadows, in the documents' canonical
    order: owner name, then face number), ``document`` (the JSON document of ``penumbra
    shadows``, as dicts and lists) and ``warnings``."""

    def __init__(self, document, warnings):
        self.document = document
        self.warnings = list(warnings)
        self.faces = [FaceShadows(entry) for entry in document["faces"]]

    def face(self, owner, number):
        """returns the FaceShadows of face ``number`` of ``owner``."""
        for face in self.faces:
            if face.object == owner and face.face == number:
                return face
        raise KeyError(f"no face {number} of {owner!r}")

    def __iter__(self):
        return iter(self.faces)

    def __len__(self):
        return len(self.faces)

    def __repr__(self):
        return f"Shadows({len(self.faces)} faces)"
