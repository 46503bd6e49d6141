"""The point kernels of :mod:`.points` on the IVEA projection: the same code, compiled a second time.

Point location descends in the face plane after projecting, and centres and
boundaries map planar points back: the projection enters :mod:`.points` only
through ``gk.forward_unit`` and ``gk.inverse_unit`` (:mod:`dggs.geometry.kernel`).
Here each function of :mod:`.points` that calls them (directly or through
another) is rebuilt from its own code object with ``gk`` bound to a copy of
the geometry kernel whose two entries are IVEA's
(:func:`dggs.geometry.ivea.forward_unit`, :func:`dggs.geometry.ivea.face_inverse`,
the same signatures).  Nothing is written twice and :mod:`.points`, and so
every ISEA id, is untouched.  What does not project (``encode_point``,
``corners``, ``triangle``, the pole table: the poles sit on the same planar
edge midpoints in both projections) is shared as compiled.

Each rebuilt function gets the qualified name ``ivea__<name>``, so numba's
disk cache keeps it apart from the ISEA original.
"""

from __future__ import annotations

import types
from typing import Any

import numba

from dggs.geometry import ivea as _ivea
from dggs.geometry import kernel as _gk
from dggs.geometry._parallel import loops

from . import points as _points


def _ivea_kernel() -> types.ModuleType:
    """A module with the geometry kernel's names, ``forward_unit`` and ``inverse_unit`` IVEA's."""
    mod = types.ModuleType("dggs.geometry.kernel_ivea")
    mod.__dict__.update({k: v for k, v in vars(_gk).items() if not k.startswith("__")})
    mod.forward_unit = _ivea.forward_unit  # type: ignore[attr-defined]
    mod.inverse_unit = _ivea.face_inverse  # type: ignore[attr-defined]
    return mod


IVEA_KERNEL = _ivea_kernel()


def rebuilder(module: types.ModuleType) -> tuple[dict[str, Any], Any, Any]:
    """``(globals, rebuilt, compiled)`` for rebuilding functions of a kernel ``module`` on IVEA.

    ``globals`` is a copy of the module's namespace with ``gk`` bound to :data:`IVEA_KERNEL`;
    ``rebuilt(name)`` gives the plain function ``name`` over it, renamed ``ivea__<name>``;
    ``compiled(name, **options)`` compiles that (``cache=True, nogil=True`` unless given) and puts it in
    ``globals``, so that functions rebuilt after it call it.
    """
    space: dict[str, Any] = dict(vars(module))
    space["gk"] = IVEA_KERNEL

    def rebuilt(name: str) -> Any:
        obj = getattr(module, name)
        body = getattr(obj, "py_func", obj)
        twin = types.FunctionType(body.__code__, space, body.__name__, body.__defaults__, body.__closure__)
        twin.__qualname__ = f"ivea__{body.__qualname__}"
        twin.__doc__ = body.__doc__
        return twin

    def compiled(name: str, **options: Any) -> Any:
        fn = numba.njit(**(options or {"cache": True, "nogil": True}))(rebuilt(name))
        space[name] = fn
        return fn

    return space, rebuilt, compiled


_GLOBALS, _rebuilt, _compiled = rebuilder(_points)

# the per-item functions that reach the projection, callees first
one_point = _compiled("one_point")
_one_centre = _compiled("_one_centre")
_edge_points = _compiled("_edge_points")
_one_boundary = _compiled("_one_boundary")
_lat_lng_at = _compiled("_lat_lng_at")
_crossing = _compiled("_crossing")
special_ring = _compiled("special_ring")
centre_of = _compiled("centre_of")
# the batch loops
locate = loops(_rebuilt("_locate"))
centres = loops(_rebuilt("_centres"))
boundaries = loops(_rebuilt("_boundaries"))
SPECIAL_EXTRA = _points.SPECIAL_EXTRA

__all__ = ["one_point", "centre_of", "special_ring", "locate", "centres", "boundaries", "SPECIAL_EXTRA",
           "IVEA_KERNEL", "rebuilder"]
