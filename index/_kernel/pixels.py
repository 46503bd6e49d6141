"""Compiled exact weights of polygons in cells: each polygon cut along cell edges in Snyder's face planes.

Snyder's projection is equal-area and maps every cell to a planar triangle
with straight edges (thesis §6.1.7): the area of a polygon's part inside a
cell is the planar area, in the cell's face plane, of the polygon clipped by
the cell's triangle, times one constant.  So :func:`pieces` finds, for each
polygon (a raster pixel, its edges densified by the caller), every cell of a
level it meets and the planar area they share, by descending the hierarchy:

* a polygon whose vertices all lie in one cell of the level lies wholly in it
  (cells are convex): one piece, its whole area;
* otherwise it is clipped (Sutherland-Hodgman against each child triangle, a
  convex window) from the smallest cell holding all its vertices down to the
  level; a triangle the polygon covers wholly gives all its descendants at the
  level, an equal share each (cells are congruent in the plane);
* a polygon across face edges is projected onto each face near it (Snyder's
  forward on that face: the sector formulas hold past the face's edges) and
  clipped by that face's triangle first, so each face keeps its own part.

Areas are planar, in the unit-sphere face frame; the caller scales them to
m² (:data:`FACE_AREA` is one face's planar area, 1/20 of the sphere).  The
polygons' edges are chords in the face plane: the caller densifies them.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from dggs.geometry import kernel as gk
from dggs.geometry.icosahedron import ISEA  # noqa: E402 - the faces' vertices, for their boundaries

from . import bits
from .clip import area, clip, descend, grow
from .points import encode_point, triangle

_FRAMES = gk.ISEA_FRAMES
_CENTRES = gk.ISEA_CENTRES
_HALF_SQRT3 = 0.5 * math.sqrt(3.0)
_FACE = gk.FACE_CORNERS_CCW
_L1 = gk.LEVEL1_CORNERS


def _facearea() -> float:
    x, y = _FACE[:, 0], _FACE[:, 1]
    return float(0.5 * abs(x[0] * (y[1] - y[2]) + x[1] * (y[2] - y[0]) + x[2] * (y[0] - y[1])))


#: Planar area of a face triangle in the unit-sphere face frame (a twentieth of the sphere's 4 pi).
FACE_AREA = _facearea()
#: Faces whose triangle may meet a polygon within this angle (radians) of one of its vertices: the face's
#: circumradius (37.38 degrees) and the largest polygon :func:`pieces` takes (:data:`MAX_RADIUS`).
MAX_RADIUS = math.radians(10.0)
_REACH = math.cos(math.radians(37.3774) + MAX_RADIUS + 1e-6)


def _boundaries() -> np.ndarray:
    """(20, 6, 3): per face the unit normals of the great circles its plane bends along.

    Snyder's forward is smooth inside each of a face's three 120-degree sectors but kinks where a
    sector ends, along the rays from the face centre to its vertices, and where the face ends, along
    its edges: all great-circle arcs.  A pixel edge crossing one is drawn with a point on it.
    """
    geo = ISEA.geometry
    out = np.empty((geo.centres.shape[0], 6, 3))
    for f in range(out.shape[0]):
        v = geo.vertices[geo.face_vertices[f]]
        for k in range(3):
            out[f, k] = np.cross(geo.centres[f], v[k])
            out[f, 3 + k] = np.cross(v[k], v[(k + 1) % 3])
    return np.ascontiguousarray(out / np.linalg.norm(out, axis=2, keepdims=True))


_BOUNDS = _boundaries()


@njit(cache=True, nogil=True)
def chord_errors(lat: np.ndarray, lng: np.ndarray) -> np.ndarray:
    """Per pixel, the fraction of its area its edges' chords leave out (one point an edge).

    ``lat``, ``lng`` (N, 16): a pixel's points round it, four an edge (its first corner, then at a
    quarter, half and three quarters).  A chord of length L whose curve's middle lies ``s`` off it
    leaves out ``2/3 s L`` (a parabola's segment).  Each half-edge's is measured from its three
    points, in the face planes of the faces the points lie on (each bends the edge its own way);
    a half across a kink (:func:`region`) takes the other half's (the kink's crossing is drawn,
    :func:`_kinked`), or, where both are, the bend of the pixel's smoothest-measured half; a whole
    edge's is 8 times its halves' mean (s grows as L²).  NaN where no half-edge is smooth.
    """
    out = np.zeros(lat.shape[0])
    ux, uy, uz = np.empty(16), np.empty(16), np.empty(16)
    faces = np.empty(16, np.int64)
    regs = np.empty(16, np.int64)
    x, y = np.empty(16), np.empty(16)
    for i in range(lat.shape[0]):
        for j in range(16):
            ux[j], uy[j], uz[j] = gk.geodetic_to_unit(lat[i, j], lng[i, j])
            faces[j] = gk.nearest_face(_CENTRES, ux[j], uy[j], uz[j])
            regs[j] = region(faces[j], ux[j], uy[j], uz[j])
        for j in range(16):
            f = faces[j]
            if j > 0 and f in faces[:j]:
                continue
            for q in range(16):
                x[q], y[q] = gk.face_forward(_FRAMES, f, ux[q], uy[q], uz[q])
            twice = 0.0
            lost = 0.0
            ratio = -1.0  # the largest lost / length² of a smooth half-edge: how the pixel's edges bend
            bent = 0.0  # the squared lengths of the halves to take that ratio (both halves of an edge kinked)
            for e in range(4):
                twice += x[4 * e] * y[(4 * e + 4) % 16] - x[(4 * e + 4) % 16] * y[4 * e]
                half = 0.0
                smooth = 0
                for h in range(2):
                    a, m, b = 4 * e + 2 * h, 4 * e + 2 * h + 1, (4 * e + 2 * h + 2) % 16
                    length = math.hypot(x[b] - x[a], y[b] - y[a])
                    if regs[a] != regs[m] or regs[m] != regs[b]:
                        if h == 1 and smooth == 0:
                            bent += 2.0 * length * length
                        continue
                    one = 2.0 / 3.0 * math.hypot(x[m] - 0.5 * (x[a] + x[b]), y[m] - 0.5 * (y[a] + y[b])) * length
                    half += one
                    smooth += 1
                    if length > 0.0:
                        ratio = max(ratio, one / (length * length))
                if smooth:
                    lost += 8.0 * half / smooth
            if ratio < 0.0:
                out[i] = np.nan  # no smooth half-edge to measure: the caller takes its neighbours'
                break
            lost += 8.0 * ratio * bent
            if twice != 0.0 and not np.isnan(out[i]):
                out[i] = max(out[i], lost / abs(0.5 * twice))
    return out


@njit(cache=True, nogil=True)
def region(face: int, ux: float, uy: float, uz: float) -> int:
    """``3 face + sector``: the sector (0..2) as :func:`dggs.geometry.kernel.face_forward` picks it."""
    n = _FRAMES[face, 1, 0] * ux + _FRAMES[face, 1, 1] * uy + _FRAMES[face, 1, 2] * uz
    e = _FRAMES[face, 2, 0] * ux + _FRAMES[face, 2, 1] * uy + _FRAMES[face, 2, 2] * uz
    if e >= 0.0 and -0.5 * e - _HALF_SQRT3 * n < 0.0 and not (e == 0.0 and n < 0.0):
        return 3 * face
    if e < 0.0 and -0.5 * e + _HALF_SQRT3 * n >= 0.0:
        return 3 * face + 2
    return 3 * face + 1


@njit(cache=True, nogil=True)
def _kinked(ux, uy, uz, ring, m, regions, faces, near, ox, oy, oz) -> int:
    """The ring's points with, between two in different regions, the crossings of the bending circles.

    The circles are those of ``faces`` where ``near``; a crossing lies on the great circle through
    the two points (a pixel's edge between two of its points, to within their chord) and on the
    circle, so every face plane draws it on its kink.  Writes unit vectors; returns their count.
    """
    out = 0
    ts = np.empty(6 * _BOUNDS.shape[0])
    cx, cy, cz = np.empty(ts.shape[0]), np.empty(ts.shape[0]), np.empty(ts.shape[0])
    for j in range(m):
        a, b = ring[j], ring[(j + 1) % m]
        ox[out], oy[out], oz[out] = ux[a], uy[a], uz[a]
        out += 1
        if regions[a] == regions[b]:
            continue
        mx = uy[a] * uz[b] - uz[a] * uy[b]  # the normal of the great circle through a and b
        my = uz[a] * ux[b] - ux[a] * uz[b]
        mz = ux[a] * uy[b] - uy[a] * ux[b]
        found = 0
        for f in range(_BOUNDS.shape[0]):
            if not near[f]:
                continue
            for q in range(6):
                nx, ny, nz = _BOUNDS[f, q, 0], _BOUNDS[f, q, 1], _BOUNDS[f, q, 2]
                dx, dy, dz = my * nz - mz * ny, mz * nx - mx * nz, mx * ny - my * nx
                norm = math.sqrt(dx * dx + dy * dy + dz * dz)
                if norm == 0.0:
                    continue
                if dx * (ux[a] + ux[b]) + dy * (uy[a] + uy[b]) + dz * (uz[a] + uz[b]) < 0.0:
                    norm = -norm
                dx, dy, dz = dx / norm, dy / norm, dz / norm
                # strictly between a and b along their arc
                sa = (uy[a] * dz - uz[a] * dy) * mx + (uz[a] * dx - ux[a] * dz) * my + (ux[a] * dy - uy[a] * dx) * mz
                sb = (dy * uz[b] - dz * uy[b]) * mx + (dz * ux[b] - dx * uz[b]) * my + (dx * uy[b] - dy * ux[b]) * mz
                if sa <= 0.0 or sb <= 0.0:
                    continue
                ts[found] = sa / (sa + sb)
                cx[found], cy[found], cz[found] = dx, dy, dz
                found += 1
        for i in np.argsort(ts[:found]):
            ox[out], oy[out], oz[out] = cx[i], cy[i], cz[i]
            out += 1
    return out


@njit(cache=True, nogil=True)
def _common(cells: np.ndarray, count: int, target: int) -> int:
    """The finest level at which the cells share an ancestor (they are on one face)."""
    for lv in range(1, target + 1):
        first = bits.parent_at(cells[0], lv)
        for i in range(1, count):
            if bits.parent_at(cells[i], lv) != first:
                return lv - 1
    return target


@njit(cache=True, nogil=True)
def _ring(r, col, k, hu, vu, ring):
    """Indices into the flattened point arrays of pixel (r, col)'s ring: top, right, bottom, left edges."""
    hw = hu.shape[1]
    vw = vu.shape[1]
    if k == 1:  # the four corners, all on the lines of constant row (the others are the same points)
        ring[0], ring[1] = r * hw + col, r * hw + col + 1
        ring[2], ring[3] = (r + 1) * hw + col + 1, (r + 1) * hw + col
        return 4
    m = 0
    for j in range(k):  # top edge, left to right
        ring[m] = r * hw + col * k + j
        m += 1
    for j in range(k):  # right edge, top to bottom (vertical points follow the horizontal ones)
        ring[m] = hu.size + (r * k + j) * vw + col + 1
        m += 1
    for j in range(k):  # bottom edge, right to left
        ring[m] = (r + 1) * hw + (col + 1) * k - j
        m += 1
    for j in range(k):  # left edge, bottom to top
        ring[m] = hu.size + ((r + 1) * k - j) * vw + col
        m += 1
    return m


@njit(cache=True, nogil=True)
def grid_pieces(hlat, hlng, vlat, vlng, k: int, valid: np.ndarray, target: int):
    """Cells at level ``target`` met by each pixel of a grid, and the planar area they share.

    The pixels' edges, densified with ``k`` points each: ``hlat``, ``hlng``
    (R + 1, C k + 1) along the R + 1 grid lines of constant row, ``vlat``,
    ``vlng`` (R k + 1, C + 1) along the C + 1 of constant column (degrees,
    WGS84; each corner in both).  Pixel (r, c) is number ``r C + c``; pixels
    where ``valid`` (R, C) is False are left out.  Returns ``(pixel, cell,
    area, coarse)``, each pixel's pieces together in pixel order, areas in the
    unit-sphere face plane (:data:`FACE_AREA` a face); ``coarse`` (R C) is,
    for an even ``k``, the planar area of each pixel drawn through every other
    of its points (for the extrapolation of :func:`dggs.index._pixels.pixel_pieces`),
    NaN for pixels across a kink of the plane (and for all with an odd ``k``).
    A pixel must lie within :data:`MAX_RADIUS` of its corners.
    """
    rows, cols = valid.shape
    npts = hlat.size + (vlat.size if k > 1 else 0)  # with one point an edge, the corners are all in hlat
    ux, uy, uz = np.empty(npts), np.empty(npts), np.empty(npts)
    fx, fy = np.empty(npts), np.empty(npts)
    faces = np.empty(npts, np.int64)
    regions = np.empty(npts, np.int64)
    cells = np.empty(npts, np.uint64)
    hl, hg, vl, vg = hlat.ravel(), hlng.ravel(), vlat.ravel(), vlng.ravel()
    for i in range(npts):  # every point once: shared by the pixels on both sides
        la, lo = (hl[i], hg[i]) if i < hl.size else (vl[i - hl.size], vg[i - hl.size])
        ux[i], uy[i], uz[i] = gk.geodetic_to_unit(la, lo)
        faces[i] = gk.nearest_face(_CENTRES, ux[i], uy[i], uz[i])
        regions[i] = region(faces[i], ux[i], uy[i], uz[i])
        fx[i], fy[i] = gk.face_forward(_FRAMES, faces[i], ux[i], uy[i], uz[i])
        cells[i] = encode_point(faces[i], fx[i], fy[i], target)
    m = 4 * k
    most = 8 * m + 64  # a ring's points with the kinks' crossings
    width = most + 3 * (target + 4) + 8
    ring = np.empty(m, np.int64)
    px, py = np.empty(width), np.empty(width)
    rc = np.empty(m, np.uint64)
    kx, ky = np.empty((target + 3, 6, width)), np.empty((target + 3, 6, width))
    kn = np.zeros((target + 3, 6), np.int64)
    tx, ty = np.empty(width), np.empty(width)
    qx, qy = np.empty(width), np.empty(width)
    wx, wy, wz = np.empty(most), np.empty(most), np.empty(most)
    tri6 = np.empty((target + 3, 6))
    ids = np.empty(target + 3, np.uint64)
    nxt = np.zeros(target + 3, np.int64)
    near = np.zeros(_CENTRES.shape[0], np.bool_)
    face_tri = np.array([_FACE[0, 0], _FACE[0, 1], _FACE[1, 0], _FACE[1, 1], _FACE[2, 0], _FACE[2, 1]])
    p = np.empty(max(16, 2 * rows * cols), np.int64)
    c = np.empty(p.shape[0], np.uint64)
    a = np.empty(p.shape[0], np.float64)
    coarse = np.full(rows * cols, np.nan)
    root_tri = np.empty(6)
    half = m // 2 if k >= 2 and k % 2 == 0 else 0
    n = 0
    for r in range(rows):
        for col in range(cols):
            if not valid[r, col]:
                continue
            pixel = r * cols + col
            _ring(r, col, k, hlat, vlat, ring)
            f = faces[ring[0]]
            one_face = True
            one_region = True
            one_cell = True
            for j in range(m):
                q = ring[j]
                px[j], py[j], rc[j] = fx[q], fy[q], cells[q]
                one_face &= faces[q] == f
                one_region &= regions[q] == regions[ring[0]]
                one_cell &= cells[q] == rc[0]
            if one_region:  # in one sector of one face, where the plane does not bend
                if half:  # the ring through every other point (corners included)
                    for j in range(half):
                        qx[j], qy[j] = px[2 * j], py[2 * j]
                    coarse[pixel] = abs(area(qx, qy, half))
                if one_cell:  # every vertex in one cell: the pixel lies in it (cells are convex)
                    got = abs(area(px, py, m))
                    if got > 0.0:
                        p, c, a = grow(p, c, a, n, 1)
                        p[n], c[n], a[n] = pixel, rc[0], got
                        n += 1
                    continue
                level = _common(rc, m, target)
                root = bits.parent_at(rc[0], level)
                if level == 0:
                    root_tri[:] = face_tri
                else:
                    _, root_tri[0], root_tri[1], root_tri[2], root_tri[3], root_tri[4], root_tri[5] = triangle(root)
                p, c, a, n = descend(root, level, root_tri, target, px, py, m, pixel, p, c, a, n, kx, ky, kn, tx, ty, tri6,
                                     ids, nxt)
                continue
            for g in range(_CENTRES.shape[0]):  # across sectors or faces: the faces near a vertex
                near[g] = g == f
                for j in range(m):
                    if one_face:
                        break
                    q = ring[j]
                    if ux[q] * _CENTRES[g, 0] + uy[q] * _CENTRES[g, 1] + uz[q] * _CENTRES[g, 2] >= _REACH:
                        near[g] = True
                        break
            mk = _kinked(ux, uy, uz, ring, m, regions, faces, near, wx, wy, wz)
            for g in range(_CENTRES.shape[0]):
                if not near[g]:
                    continue
                for j in range(mk):
                    px[j], py[j] = gk.face_forward(_FRAMES, g, wx[j], wy[j], wz[j])
                got_n = clip(px, py, mk, face_tri[0], face_tri[1], face_tri[2], face_tri[3], face_tri[4],
                             face_tri[5], qx, qy, tx, ty)
                got = abs(area(tx, ty, got_n))
                if got <= 0.0:
                    continue
                if target == 0:
                    p, c, a = grow(p, c, a, n, 1)
                    p[n], c[n], a[n] = pixel, bits.base_cell(g), got
                    n += 1
                    continue
                px[:got_n], py[:got_n] = tx[:got_n], ty[:got_n]
                p, c, a, n = descend(bits.base_cell(g), 0, face_tri, target, px, py, got_n, pixel, p, c, a, n,
                                     kx, ky, kn, tx, ty, tri6, ids, nxt)
    return p[:n], c[:n], a[:n], coarse
