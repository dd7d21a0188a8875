# Type stubs of the package penumbra (python/penumbra/__init__.py, _shadows.py).
import os
from fractions import Fraction
from typing import Any, Iterator, NamedTuple, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

from ._penumbra import InputError as InputError
from ._penumbra import format_json as format_json
from ._penumbra import solar_position as solar_position

Path = Union[str, os.PathLike[str]]
Receivers = Union[None, str, Sequence[str]]
ExactPoint = tuple[Fraction, Fraction, Fraction]

class Light(NamedTuple):
    name: str
    kind: str

class Frame:
    origin: npt.NDArray[np.float64]
    u: npt.NDArray[np.float64]
    v: npt.NDArray[np.float64]
    def to_frame(self, points: npt.ArrayLike) -> npt.NDArray[np.float64]: ...

class Polygon:
    outer: npt.NDArray[np.float64]
    holes: list[npt.NDArray[np.float64]]
    exact_outer: Optional[list[ExactPoint]]
    exact_holes: Optional[list[list[ExactPoint]]]
    frame: Frame
    def to_shapely(self) -> Any: ...

class PolygonSet:
    area: float
    polygons: list[Polygon]
    def __iter__(self) -> Iterator[Polygon]: ...
    def __len__(self) -> int: ...
    def to_shapely(self) -> Any: ...

class LightShadows:
    light: str
    shadow: PolygonSet
    umbra: PolygonSet
    penumbra: PolygonSet
    lit: PolygonSet
    faces_away: bool
    joint_occlusion: bool
    source_clipped: bool
    occluders: list[dict[str, Any]]

class FaceShadows:
    object: str
    face: int
    plane: npt.NDArray[np.float64]
    exact_plane: Optional[tuple[Fraction, Fraction, Fraction, Fraction]]
    frame: Frame
    boundary: Polygon
    area: float
    lights: dict[str, LightShadows]

class Shadows:
    document: dict[str, Any]
    warnings: list[str]
    faces: list[FaceShadows]
    def face(self, owner: str, number: int) -> FaceShadows: ...
    def __iter__(self) -> Iterator[FaceShadows]: ...
    def __len__(self) -> int: ...

class Workplane:
    points: npt.NDArray[np.float64]
    values: npt.NDArray[np.float64]
    per_light: dict[str, npt.NDArray[np.float64]]
    inside: npt.NDArray[np.int64]
    columns: int
    rows: int
    region: tuple[float, float, float, float]
    def grid(self) -> npt.NDArray[np.float64]: ...
    def statistics(self) -> dict[str, float]: ...

class SunHours:
    document: dict[str, Any]
    warnings: list[str]
    @property
    def faces(self) -> list[dict[str, Any]]: ...
    @property
    def longest_minutes(self) -> float: ...
    def to_json(self) -> str: ...
    def write_json(self, path: Path) -> None: ...
    def write_svg(self, path: Path, view: str = ...) -> None: ...
    def write_png(self, path: Path, width: int = ...) -> None: ...

class Scene:
    @classmethod
    def load(cls, path: Path) -> Scene: ...
    @classmethod
    def from_dict(cls, document: dict[str, Any], base_dir: Optional[Path] = ...,
                  name: str = ...) -> Scene: ...
    @property
    def file(self) -> str: ...
    @property
    def objects(self) -> list[str]: ...
    @property
    def lights(self) -> list[Light]: ...
    @property
    def suns(self) -> list[str]: ...
    @property
    def warnings(self) -> list[str]: ...
    def owners(self) -> list[tuple[str, int, tuple[float, float, float, float, float, float]]]: ...
    def shadow_document(self, light: Optional[str] = ..., receivers: Receivers = ...,
                        exact: bool = ..., range_fraction: float = ..., full_scale_lux: float = ...,
                        range_lux: Optional[float] = ...) -> tuple[dict[str, Any], list[str]]: ...
    def shadows(self, light: Optional[str] = ..., receivers: Receivers = ..., exact: bool = ...,
                **culling: float) -> Shadows: ...
    def illuminance(self, points: npt.ArrayLike, per_light: bool = ..., inside: bool = ...) -> Any: ...
    def workplane(self, height: float, spacing: float,
                  region: Optional[Sequence[float]] = ...) -> Workplane: ...
    def workplane_grid(self, height: float, spacing: float, region: Optional[Sequence[float]] = ...
                       ) -> tuple[npt.NDArray[np.float64], int, int,
                                  tuple[float, float, float, float]]: ...
    def sun_shadows(self, time: str, light: Optional[str] = ..., exact: bool = ...,
                    receivers: Receivers = ..., range_fraction: float = ...,
                    full_scale_lux: float = ..., range_lux: Optional[float] = ...) -> Shadows: ...
    def sun_hours(self, date: Optional[str] = ..., step: str = ..., to: Optional[str] = ...,
                  light: Optional[str] = ..., site: Optional[str] = ...,
                  utc_offset: Optional[str] = ..., receivers: Receivers = ...,
                  exact: bool = ...) -> SunHours: ...
    def sun_steps(self, date: Optional[str] = ..., step: str = ..., to: Optional[str] = ...,
                  light: Optional[str] = ..., site: Optional[str] = ...,
                  utc_offset: Optional[str] = ...
                  ) -> list[tuple[str, float, float, float, float, float, bool]]: ...
