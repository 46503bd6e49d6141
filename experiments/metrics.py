"""Per-level measurements of thesis §6.2-6.3 (Tables 6.1-6.7).

Examples
--------
>>> from dggs.experiments.mesh import icosahedron
>>> m = measure(icosahedron(), level=0, base_area=None)
>>> m.faces, round(m.avg_displacement_pct, 2)
(20, 20.53)
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from dggs.experiments.mesh import Mesh, face_areas, face_centres, total_area

__all__ = ["EARTH_RADIUS_KM", "EARTH_AREA_KM2", "LevelMetrics", "measure", "JSON_KEYS"]

#: Earth's mean radius used by the thesis for Table 6.5 (§6.3.3).
EARTH_RADIUS_KM = 6371.0
#: Earth's surface area used by the thesis for Table 6.7 (§6.3.3).
EARTH_AREA_KM2 = 510_072_000.0

#: Keys of the ``--json`` output, in order.
JSON_KEYS = (
    "level",
    "faces",
    "area_deviation_pct",
    "avg_displacement_pct",
    "max_displacement_pct",
    "avg_displacement_km",
    "max_face_error_pct",
    "max_face_error_km2",
)


@dataclass(frozen=True)
class LevelMetrics:
    """The thesis's measurements for one subdivision level.

    Attributes
    ----------
    level, faces : int
        Subdivision level and face count (Table 6.2).
    area_deviation_pct : float
        ``100 (sum of face areas / base area - 1)`` (Table 6.1).
    avg_displacement_pct, max_displacement_pct : float
        ``100 (1 - |face centre| / R)`` averaged / maximised over faces,
        where the centre is the vertex average and ``R`` the circumscribing
        radius (Tables 6.3, 6.4, Figure 6.13).
    avg_displacement_km, max_displacement_km : float
        The same on a 6,371 km Earth (Table 6.5).
    max_face_error_pct : float
        ``max |A_face / A_expected - 1| * 100`` with
        ``A_expected = base area / faces`` (§6.3.2, Table 6.6).
    max_face_error_km2 : float
        That error on a 510,072,000 km^2 Earth as the thesis computes it
        (Table 6.7): ``max_face_error_pct / 100 * Earth * (1 + deviation) / F``,
        the mesh's own total area standing for the Earth (the factor is 1 where
        the area is preserved; with it Table 6.7's Catmull-Clark and 1:5 cells
        follow from Tables 6.1 and 6.6).
    face_errors_pct : numpy.ndarray
        Signed per-face errors (``+`` = too big), for the figures.
    """

    level: int
    faces: int
    area_deviation_pct: float
    avg_displacement_pct: float
    max_displacement_pct: float
    avg_displacement_km: float
    max_displacement_km: float
    max_face_error_pct: float
    max_face_error_km2: float
    face_errors_pct: np.ndarray = field(repr=False, compare=False)

    def to_json(self) -> dict[str, float | int]:
        """The ``--json`` object for this level (keys :data:`JSON_KEYS`)."""
        d = asdict(self)
        return {k: d[k] for k in JSON_KEYS}


def measure(
    mesh: Mesh,
    level: int,
    base_area: float | None,
    areas: np.ndarray | None = None,
    radius: float | None = None,
) -> LevelMetrics:
    """Measure one level as in thesis §6.2.

    Parameters
    ----------
    mesh : Mesh
        The (rescaled) mesh of this level.
    level : int
        Its level number.
    base_area : float or None
        Surface area of the base polyhedron (``None``: this mesh's own).
    areas : numpy.ndarray, optional
        Face areas to use instead of :func:`~dggs.experiments.mesh.face_areas`
        (the dggs grid row measures spherical areas).
    radius : float, optional
        Circumscribing radius (default: mean vertex norm).

    Returns
    -------
    LevelMetrics

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> measure(icosahedron(), 0, None).max_face_error_pct
    0.0
    """
    a = face_areas(mesh) if areas is None else np.asarray(areas, dtype=np.float64)
    total = math.fsum(a.tolist()) if areas is not None else total_area(mesh)
    base = total if base_area is None else base_area
    n = len(a)
    r = float(np.linalg.norm(mesh.vertices, axis=1).mean()) if radius is None else radius
    disp = 1.0 - np.linalg.norm(face_centres(mesh), axis=1) / r  # Figure 6.13
    errors = (a / (base / n) - 1.0) * 100.0  # §6.3.2, A_expected = A_net / n_faces
    max_err = float(np.abs(errors).max())
    return LevelMetrics(
        level=level,
        faces=n,
        area_deviation_pct=(total / base - 1.0) * 100.0,
        avg_displacement_pct=float(disp.mean() * 100.0),
        max_displacement_pct=float(disp.max() * 100.0),
        avg_displacement_km=float(disp.mean() * EARTH_RADIUS_KM),
        max_displacement_km=float(disp.max() * EARTH_RADIUS_KM),
        max_face_error_pct=max_err,
        max_face_error_km2=max_err / 100.0 * EARTH_AREA_KM2 * (total / base) / n,
        face_errors_pct=errors,
    )
