"""The seven subdivision schemes of thesis chapter 6 and a runner over levels.

Every level is: refine (new vertices onto the current sphere, §6.2), then
rescale about the origin so the total area equals the base polyhedron's
(§5.1.2), then measure (§6.2-6.3).

Examples
--------
>>> [round(m.max_face_error_pct, 2) for m in run_scheme("1:4", 2)]
[0.0, 13.42, 18.64]
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from dggs.experiments.errors import ExperimentLevelError, UnknownSchemeError
from dggs.experiments.mesh import Mesh, dodecahedron, icosahedron, total_area
from dggs.experiments.metrics import LevelMetrics, measure
from dggs.experiments.preservation import rescale_to_area
from dggs.experiments.split_2_6 import split_2_6
from dggs.experiments.split_polygons import catmull_clark, split_1_5
from dggs.experiments.split_triangles import split_1_3, split_1_4, split_1_6, split_1_9

__all__ = [
    "Scheme",
    "SCHEMES",
    "MAX_FACES",
    "get_scheme",
    "max_level",
    "iter_levels",
    "run_scheme",
]

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
    """

    key: str
    title: str
    base: Callable[[], Mesh]
    step: Callable[[Mesh, int], Mesh]
    thesis_levels: int

    def faces(self, level: int) -> int:
        """Face count at ``level`` (Table 6.2), by formula.

        Examples
        --------
        >>> SCHEMES["2:6"].faces(7), SCHEMES["1:5"].faces(7)
        (87480, 21872)
        """
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

_ALIASES = {"cc": "catmull-clark", "catmull": "catmull-clark", "catmull_clark": "catmull-clark"}


def get_scheme(name: str) -> Scheme:
    """Look a scheme up by CLI name.

    Raises
    ------
    UnknownSchemeError
        If ``name`` is not a scheme.

    Examples
    --------
    >>> get_scheme("cc").title
    'Catmull-Clark, §6.1.3'
    >>> get_scheme("1:7")
    Traceback (most recent call last):
    ...
    dggs.experiments.errors.UnknownSchemeError: unknown scheme '1:7'; choose one of 1:4, 1:9, catmull-clark, 1:3, 1:6, 1:5, 2:6
    """
    key = _ALIASES.get(str(name).lower(), str(name).lower())
    if key not in SCHEMES:
        raise UnknownSchemeError(f"unknown scheme {name!r}; choose one of {', '.join(SCHEMES)}")
    return SCHEMES[key]


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
    name: str | Scheme, levels: int, progress: bool = False
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

    Raises
    ------
    UnknownSchemeError, ExperimentLevelError
        On a bad name or level count.

    Examples
    --------
    >>> [m.faces for _, m in iter_levels("1:5", 2)]
    [12, 32, 92]
    """
    scheme = name if isinstance(name, Scheme) else get_scheme(name)
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
            mesh = rescale_to_area(scheme.step(mesh, level), base_area)  # thesis §5.1.2
            yield mesh, measure(mesh, level, base_area)
            if bar is not None:
                bar.update(1)
    finally:
        if bar is not None:
            bar.close()


def run_scheme(name: str | Scheme, levels: int, progress: bool = False) -> list[LevelMetrics]:
    """Metrics of a scheme at levels ``0..levels`` (Tables 6.1-6.7).

    Examples
    --------
    >>> [m.faces for m in run_scheme("catmull-clark", 2)]
    [20, 60, 240]
    """
    return [m for _, m in iter_levels(name, levels, progress)]
