"""Global (net) area preservation of thesis §5.1.2.

After a refinement has pushed its new vertices onto the common sphere, every
vertex is scaled along its normal from the origin so that the total surface
area equals the base polyhedron's:

    R_{i+1} = sqrt(SA * R_i**2 / SA'_i)        (thesis §5.1.2)

Examples
--------
>>> from dggs.experiments.mesh import icosahedron, total_area
>>> from dggs.experiments.split_triangles import split_1_4
>>> ico = icosahedron()
>>> fine = rescale_to_area(split_1_4(ico), total_area(ico))
>>> abs(total_area(fine) / total_area(ico) - 1) < 1e-12
True
"""

from __future__ import annotations

import math

import numpy as np

from dggs.experiments.mesh import Mesh, total_area

__all__ = ["rescale_to_area", "circumradius"]


def circumradius(mesh: Mesh) -> float:
    """Mean distance of the vertices from the origin.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron
    >>> round(circumradius(icosahedron(2.0)), 12)
    2.0
    """
    return float(np.linalg.norm(mesh.vertices, axis=1).mean())


def rescale_to_area(mesh: Mesh, target_area: float) -> Mesh:
    """Scale a sphere-inscribed mesh about the origin to a given total area.

    Parameters
    ----------
    mesh : Mesh
        Mesh whose vertices share one circumscribing sphere.
    target_area : float
        Surface area to reach (the base polyhedron's, §5.1.2).

    Returns
    -------
    Mesh
        Same faces; vertices on the sphere of radius
        ``R * sqrt(target_area / area)``.

    Examples
    --------
    >>> from dggs.experiments.mesh import icosahedron, total_area
    >>> m = rescale_to_area(icosahedron(), 4 * total_area(icosahedron()))
    >>> round(circumradius(m), 12)
    2.0
    """
    area = total_area(mesh)
    factor = math.sqrt(target_area / area)  # thesis §5.1.2: R' = sqrt(SA R^2 / SA')
    return mesh.with_vertices(mesh.vertices * factor)
