"""The seven subdivision schemes of thesis chapter 6 and a runner over levels.

Every level is: refine (new vertices onto the current sphere, §6.2), then
rescale about the origin so the total area equals the base polyhedron's
(§5.1.2), then measure (§6.2-6.3).

Each scheme comes in two variants where the thesis's rule and dggs's differ
(:data:`THESIS_SCHEMES`; ``variant="thesis"`` / ``"dggs"``): Split (2:6)
with the thesis's fixed-fraction placement, Catmull-Clark with the standard
point rules rescaled from the raw mesh before projecting, and Split (1:5)
with the thesis's vertex rule and no rescale.  The other four schemes are
the thesis's rules already (Split (1:9)'s edge thirds are our choice: the
thesis does not say).

Examples
--------
>>> [round(m.max_face_error_pct, 2) for m in run_scheme("1:4", 2)]
[0.0, 13.42, 18.64]
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from dggs.experiments.errors import ExperimentLevelError, UnknownSchemeError
from dggs.experiments.mesh import Mesh, dodecahedron, icosahedron, normalize, total_area
from dggs.experiments.metrics import LevelMetrics, measure
from dggs.experiments.preservation import rescale_to_area
from dggs.experiments.split_2_6 import split_2_6
from dggs.experiments.split_polygons import catmull_clark, split_1_5
from dggs.experiments.split_triangles import split_1_3, split_1_4, split_1_6, split_1_9

__all__ = [
    "Scheme",
    "SCHEMES",
    "THESIS_SCHEMES",
    "EXTRA_SCHEMES",
    "VARIANTS",
    "catmull_clark_thesis_step",
    "MAX_FACES",
    "get_scheme",
    "max_level",
    "iter_levels",
    "run_scheme",
]

#: ``"dggs"``: our rules (the default); ``"thesis"``: the thesis's own, as recovered from its tables.
VARIANTS = ("dggs", "thesis")

#: Largest face count a run may reach (about 1 GB of peak working memory).
MAX_FACES = 3_000_000


@dataclass(frozen=True)
class Scheme:
    """One refinement of thesis §6.1.

    Attributes
    ----------
    key : str
        CLI name (``"1:4"``, ``"catmull-clark"``, ...).
    title : str
        Thesis name and section.
    base : Callable[[], Mesh]
        Base polyhedron (icosahedron, or dodecahedron for 1:5).
    step : Callable[[Mesh, int], Mesh]
        Refinement from level ``L - 1`` to ``L`` (gets ``L``).
    thesis_levels : int
        Deepest level reported in the thesis's tables.
    variant : str
        ``"dggs"`` or ``"thesis"`` (see :data:`VARIANTS`).
    rescale : bool
        Whether the runner rescales every level to the base area (§5.1.2);
        ``False`` where the step rescales itself or, as the thesis's Split
        (1:5), not at all.
    """

    key: str
    title: str
    base: Callable[[], Mesh]
    step: Callable[[Mesh, int], Mesh]
    thesis_levels: int
    variant: str = "dggs"
    rescale: bool = True

    def faces(self, level: int) -> int:
        """Face count at ``level`` (Table 6.2), by formula.

        Examples
        --------
        >>> SCHEMES["2:6"].faces(7), SCHEMES["1:5"].faces(7)
        (87480, 21872)
        """
        if self.key == "latlng":  # 2^(L+1) bands x 2^(L+2) meridians
            return 8 * 4**level
        if self.key == "1:5":  # each vertex becomes a face: F' = F + V = 3F - 4
            f = 12
            for _ in range(level):
                f = 3 * f - 4
            return f
        if level == 0:
            return 20
        first, ratio = {
            "1:4": (80, 4),
            "1:9": (180, 9),
            "1:3": (60, 3),
            "1:6": (120, 6),
            "2:6": (120, 3),
            "catmull-clark": (60, 4),
        }[self.key]
        return first * ratio ** (level - 1)


def _step_2_6(mesh: Mesh, level: int) -> Mesh:
    return split_1_6(mesh) if level == 1 else split_2_6(mesh)  # thesis §6.1.7


def _step_2_6_thesis(mesh: Mesh, level: int) -> Mesh:
    return split_1_6(mesh) if level == 1 else split_2_6(mesh, "thesis")


@lru_cache(maxsize=1)
def _icosahedron_area() -> float:
    return total_area(icosahedron())


def catmull_clark_thesis_step(mesh: Mesh, level: int = 0) -> Mesh:
    """The thesis's Catmull-Clark level: standard point rules, rescale from the raw mesh, then project.

    The new sphere's radius is ``R0 sqrt(SA / SA')`` with ``SA`` the base
    icosahedron's area, ``R0 = 1`` its circumradius and ``SA'`` the area of
    the raw (unprojected, smoothed) mesh; every vertex is then pushed onto
    that sphere.  The projected mesh is not rescaled again, so its area
    overshoots and undershoots in turn: Table 6.1's 55.78, -11.16, 49.75 ... %.

    Examples
    --------
    >>> m = catmull_clark_thesis_step(icosahedron())
    >>> round(100 * (total_area(m) / total_area(icosahedron()) - 1), 2)
    55.78
    """
    raw = catmull_clark(mesh, "standard")
    radius = math.sqrt(_icosahedron_area() / total_area(raw))  # R0 = 1: the base icosahedron's
    return raw.with_vertices(normalize(raw.vertices, radius))


SCHEMES: dict[str, Scheme] = {
    s.key: s
    for s in (
        Scheme("1:4", "Split (1:4), §6.1.1", icosahedron, lambda m, _: split_1_4(m), 6),
        Scheme("1:9", "Split (1:9), §6.1.2", icosahedron, lambda m, _: split_1_9(m), 3),
        Scheme(
            "catmull-clark", "Catmull-Clark, §6.1.3", icosahedron, lambda m, _: catmull_clark(m), 6
        ),
        Scheme("1:3", "Split (1:3), §6.1.4", icosahedron, lambda m, _: split_1_3(m), 7),
        Scheme("1:6", "Split (1:6), §6.1.5", icosahedron, lambda m, _: split_1_6(m), 4),
        Scheme("1:5", "Split (1:5), §6.1.6", dodecahedron, lambda m, _: split_1_5(m), 7),
        Scheme("2:6", "Split (2:6), §6.1.7", icosahedron, _step_2_6, 7),
    )
}

#: The thesis's own rules where they differ from dggs's (recovered from Tables 6.1-6.7).
THESIS_SCHEMES: dict[str, Scheme] = {
    s.key: s
    for s in (
        Scheme("catmull-clark", "Catmull-Clark, §6.1.3 (thesis's rule)", icosahedron, catmull_clark_thesis_step,
               6, "thesis", rescale=False),
        Scheme("1:5", "Split (1:5), §6.1.6 (thesis's rule)", dodecahedron, lambda m, _: split_1_5(m, "thesis"),
               7, "thesis", rescale=False),
        Scheme("2:6", "Split (2:6), §6.1.7 (thesis's rule)", icosahedron, _step_2_6_thesis, 7, "thesis"),
    )
}

def _step_latlng(mesh: Mesh, level: int) -> Mesh:
    from dggs.experiments.latlng_grid import latlng_level

    return latlng_level(level, float(np.linalg.norm(mesh.vertices, axis=1).mean()))


def _octahedron() -> Mesh:
    from dggs.experiments.latlng_grid import octahedron

    return octahedron()


#: Schemes beyond chapter 6: chapter 7's equal-area latitude-longitude grid (its polyhedral approximation).
EXTRA_SCHEMES: dict[str, Scheme] = {
    "latlng": Scheme("latlng", "Equal-area lat-lng grid, ch. 7 proposal (ours)", _octahedron, _step_latlng, 7),
}

_ALIASES = {
    "lat-lng": "latlng", "latlon": "latlng", "latlong": "latlng",
    "cc": "catmull-clark", "catmull": "catmull-clark", "catmull_clark": "catmull-clark",
}


def get_scheme(name: str | Scheme, variant: str = "dggs") -> Scheme:
    """Look a scheme up by CLI name and variant (``"dggs"`` or ``"thesis"``).

    The thesis variant of a scheme whose rule dggs shares (1:4, 1:9, 1:3,
    1:6) is the scheme itself.

    Raises
    ------
    UnknownSchemeError
        If ``name`` is not a scheme or ``variant`` not a variant.

    Examples
    --------
    >>> get_scheme("cc").title
    'Catmull-Clark, §6.1.3'
    >>> get_scheme("2:6", "thesis").variant, get_scheme("1:4", "thesis").variant
    ('thesis', 'dggs')
    >>> get_scheme("1:7")
    Traceback (most recent call last):
    ...
    dggs.experiments.errors.UnknownSchemeError: unknown scheme '1:7'; choose one of 1:4, 1:9, catmull-clark, 1:3, 1:6, 1:5, 2:6, latlng
    """
    if isinstance(name, Scheme):
        name = name.key
    key = _ALIASES.get(str(name).lower(), str(name).lower())
    if key in EXTRA_SCHEMES:
        if variant not in VARIANTS:
            raise UnknownSchemeError(f"unknown variant {variant!r}; choose one of {', '.join(VARIANTS)}")
        return EXTRA_SCHEMES[key]
    if key not in SCHEMES:
        raise UnknownSchemeError(
            f"unknown scheme {name!r}; choose one of {', '.join([*SCHEMES, *EXTRA_SCHEMES])}"
        )
    if variant not in VARIANTS:
        raise UnknownSchemeError(f"unknown variant {variant!r}; choose one of {', '.join(VARIANTS)}")
    return THESIS_SCHEMES.get(key, SCHEMES[key]) if variant == "thesis" else SCHEMES[key]


def max_level(scheme: Scheme) -> int:
    """Deepest level whose face count stays within :data:`MAX_FACES`.

    Examples
    --------
    >>> max_level(SCHEMES["1:4"]), max_level(SCHEMES["1:9"])
    (8, 5)
    """
    level = 0
    while scheme.faces(level + 1) <= MAX_FACES:
        level += 1
    return level


def _check_levels(scheme: Scheme, levels: int) -> None:
    if not isinstance(levels, int) or isinstance(levels, bool):
        raise ExperimentLevelError(f"levels {levels!r} is not an integer")
    top = max_level(scheme)
    if not 0 <= levels <= top:
        raise ExperimentLevelError(
            f"levels {levels} is out of range 0..{top} for scheme {scheme.key} "
            f"(level {levels} would have {scheme.faces(max(levels, 0)):,} faces; "
            f"the limit is {MAX_FACES:,})"
        )


def iter_levels(
    name: str | Scheme, levels: int, progress: bool = False, variant: str = "dggs"
) -> Iterator[tuple[Mesh, LevelMetrics]]:
    """Yield the rescaled mesh and its metrics at levels ``0..levels``.

    Parameters
    ----------
    name : str or Scheme
        Scheme name (see :data:`SCHEMES`) or object.
    levels : int
        Deepest level, ``0 <= levels <= max_level(scheme)``.
    progress : bool
        Show a tqdm progress bar (on stderr).
    variant : str
        ``"dggs"`` or ``"thesis"`` (ignored when ``name`` is a Scheme).

    Raises
    ------
    UnknownSchemeError, ExperimentLevelError
        On a bad name or level count.

    Examples
    --------
    >>> [m.faces for _, m in iter_levels("1:5", 2)]
    [12, 32, 92]
    """
    scheme = name if isinstance(name, Scheme) else get_scheme(name, variant)
    _check_levels(scheme, levels)
    mesh = scheme.base()
    base_area = total_area(mesh)
    yield mesh, measure(mesh, 0, base_area)
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=levels, desc=f"scheme {scheme.key}", unit="level", leave=False)
    try:
        for level in range(1, levels + 1):
            mesh = scheme.step(mesh, level)
            if scheme.rescale:
                mesh = rescale_to_area(mesh, base_area)  # thesis §5.1.2
            yield mesh, measure(mesh, level, base_area)
            if bar is not None:
                bar.update(1)
    finally:
        if bar is not None:
            bar.close()


def run_scheme(
    name: str | Scheme, levels: int, progress: bool = False, variant: str = "dggs"
) -> list[LevelMetrics]:
    """Metrics of a scheme at levels ``0..levels`` (Tables 6.1-6.7).

    Examples
    --------
    >>> [m.faces for m in run_scheme("catmull-clark", 2)]
    [20, 60, 240]
    >>> [round(m.area_deviation_pct, 2) for m in run_scheme("catmull-clark", 2, variant="thesis")]
    [0.0, 55.78, -11.16]
    """
    return [m for _, m in iter_levels(name, levels, progress, variant)]
