# The geometry floor (libdggs/src/geometry.c, ivea.c): the per-point maps of dggs.geometry.kernel and
# dggs.geometry.ivea as plain Python functions (tests and tools call them one point at a time), and the batch
# loops of the checked projection API (snyder.forward / inverse, ivea.forward / inverse; _checked.py).
# The shims dggs/geometry/kernel.py and ivea.py re-export them under their old names.

from libc.math cimport NAN

cdef extern from "dmath.h" nogil:  # the core's own libm functions: the same bits on every platform
    double dggs_sin(double x)
    double dggs_cos(double x)
    double dggs_atan2(double y, double x)
    double dggs_hypot(double x, double y)


cdef extern from "tables.h" nogil:
    double DGGS_DEG_PER_RAD

cdef extern from "geometry.h" nogil:
    double dggs_wrap_degrees(double lng)
    void dggs_unit_to_geodetic(double px, double py, double pz, double *lat, double *lng)
    void dggs_authalic_sincos(double sp, double cp, double *sb, double *cb)
    void dggs_geodetic_to_unit(double lat, double lng, double p[3])
    int dggs_nearest_face(const double *centres, double px, double py, double pz)
    void dggs_sector_forward(double sin_az, double cos_az, double sin_half_z, double *x, double *y)
    void dggs_snyder_face_forward(const double *frames, int face, double px, double py, double pz, double *x,
                                  double *y)
    int dggs_snyder_forward_unit(const double *centres, const double *frames, double px, double py, double pz,
                                 double *x, double *y)
    void dggs_snyder_inverse_unit(const double *frames, int face, double x, double y, double p[3])
    void dggs_ivea_face_forward(const double *frames, int face, double px, double py, double pz, double *x,
                                double *y)
    int dggs_ivea_forward_unit(const double *centres, const double *frames, double px, double py, double pz,
                               double *x, double *y)
    void dggs_ivea_inverse_unit(const double *frames, int face, double x, double y, double p[3])
    void dggs_ivea_natural_forward(double c, double n, double e, double *x, double *y)
    void dggs_ivea_natural_inverse(double x, double y, double p[3])
    int dggs_sector_of(double x, double y)
    int dggs_level1_digit(double x, double y)
    int dggs_level1_start(double x, double y, double *px, double *py)
    int dggs_descend(double *px, double *py)
    uint64_t dggs_descend4(double *px, double *py)
    void dggs_child_corners(double t[6], int digit)


# ---- checks shared by the entries below (the C functions read frames[face] and 20 centres unchecked) ----

cdef int _geometry_frames_ok(const double[:, :, ::1] frames) except -1:
    if frames.shape[1] != 3 or frames.shape[2] != 3:
        raise ValueError(f"frames must have shape (faces, 3, 3), not {tuple(frames.shape)[:3]}")
    return 0


cdef int _geometry_face_ok(const double[:, :, ::1] frames, Py_ssize_t face) except -1:
    _geometry_frames_ok(frames)
    if face < 0 or face >= frames.shape[0]:
        raise IndexError(f"face {face} is out of range 0..{frames.shape[0] - 1}")
    return 0


cdef int _geometry_centres_ok(const double[:, ::1] centres) except -1:
    if centres.shape[0] != 20 or centres.shape[1] != 3:
        raise ValueError(f"centres must have shape (20, 3), not {tuple(centres.shape)[:2]}")
    return 0


# ---- latitudes and longitudes (kernel.py) ----

def wrap_degrees(double lng):
    """A longitude reduced exactly to -180..180 (kernel.wrap_degrees)."""
    return dggs_wrap_degrees(lng)


def unit_to_geodetic(double px, double py, double pz):
    """Vector on the authalic sphere (any norm) -> geodetic WGS84 ``(lat, lng)`` degrees (kernel.unit_to_geodetic)."""
    cdef double lat, lng
    dggs_unit_to_geodetic(px, py, pz, &lat, &lng)
    return lat, lng


def authalic_sincos(double sp, double cp):
    """``(sin beta, cos beta)`` of the authalic latitude from ``sin phi``, ``cos phi`` (kernel.authalic_sincos)."""
    cdef double sb, cb
    dggs_authalic_sincos(sp, cp, &sb, &cb)
    return sb, cb


def geodetic_to_unit(double lat_deg, double lng_deg):
    """Geodetic WGS84 degrees -> unit vector ``(x, y, z)`` on the authalic sphere (kernel.geodetic_to_unit)."""
    cdef double p[3]
    dggs_geodetic_to_unit(lat_deg, lng_deg, p)
    return p[0], p[1], p[2]


# ---- Snyder's projection (kernel.py) ----

def nearest_face(const double[:, ::1] centres, double px, double py, double pz):
    """The face whose centre is nearest; near-ties go to the lower face (kernel.nearest_face)."""
    _geometry_centres_ok(centres)
    return dggs_nearest_face(&centres[0, 0], px, py, pz)


def sector_forward(double sin_az, double cos_az, double sin_half_z):
    """Snyder's forward inside one 120-degree sector: ``(rho sin Az', rho cos Az')`` (kernel.sector_forward)."""
    cdef double x, y
    dggs_sector_forward(sin_az, cos_az, sin_half_z, &x, &y)
    return x, y


def snyder_face_forward(const double[:, :, ::1] frames, Py_ssize_t face, double px, double py, double pz):
    """Unit vector -> ``(x, y)`` in the frame of ``face`` (kernel.face_forward)."""
    cdef double x, y
    _geometry_face_ok(frames, face)
    dggs_snyder_face_forward(&frames[0, 0, 0], <int>face, px, py, pz, &x, &y)
    return x, y


def snyder_forward_unit(const double[:, ::1] centres, const double[:, :, ::1] frames, double px, double py,
                        double pz):
    """Unit vector -> ``(face, x, y)`` in the face frame (kernel.forward_unit)."""
    cdef double x, y
    cdef int face
    _geometry_centres_ok(centres)
    _geometry_face_ok(frames, 19)
    face = dggs_snyder_forward_unit(&centres[0, 0], &frames[0, 0, 0], px, py, pz, &x, &y)
    return face, x, y


def snyder_inverse_unit(const double[:, :, ::1] frames, Py_ssize_t face, double x, double y):
    """Face-frame ``(x, y)`` -> unit vector ``(x, y, z)``, Snyder's closed form (kernel.inverse_unit)."""
    cdef double p[3]
    _geometry_face_ok(frames, face)
    dggs_snyder_inverse_unit(&frames[0, 0, 0], <int>face, x, y, p)
    return p[0], p[1], p[2]


def sector_of(double x, double y):
    """120-degree sector (planar azimuth // 120, clockwise from +y) by half-planes (kernel.sector_of)."""
    return dggs_sector_of(x, y)


# ---- IVEA (ivea.py) ----

def ivea_natural_forward(double c, double n, double e):
    """Unit vector ``(c, n, e)`` in the natural triangle -> planar ``(x, y)`` (ivea.natural_forward)."""
    cdef double x, y
    dggs_ivea_natural_forward(c, n, e, &x, &y)
    return x, y


def ivea_natural_inverse(double x, double y):
    """Planar ``(x, y)`` in the natural triangle -> unit vector ``(c, n, e)`` (ivea.natural_inverse)."""
    cdef double p[3]
    dggs_ivea_natural_inverse(x, y, p)
    return p[0], p[1], p[2]


def ivea_face_forward(const double[:, :, ::1] frames, Py_ssize_t face, double px, double py, double pz):
    """Unit vector -> ``(x, y)`` in the frame of ``face`` by IVEA (ivea.face_forward)."""
    cdef double x, y
    _geometry_face_ok(frames, face)
    dggs_ivea_face_forward(&frames[0, 0, 0], <int>face, px, py, pz, &x, &y)
    return x, y


def ivea_forward_unit(const double[:, ::1] centres, const double[:, :, ::1] frames, double px, double py,
                      double pz):
    """Unit vector -> ``(face, x, y)``: the nearest face, then IVEA (ivea.forward_unit)."""
    cdef double x, y
    cdef int face
    _geometry_centres_ok(centres)
    _geometry_face_ok(frames, 19)
    face = dggs_ivea_forward_unit(&centres[0, 0], &frames[0, 0, 0], px, py, pz, &x, &y)
    return face, x, y


def ivea_face_inverse(const double[:, :, ::1] frames, Py_ssize_t face, double x, double y):
    """Face-frame ``(x, y)`` -> unit vector ``(x, y, z)`` by IVEA (ivea.face_inverse)."""
    cdef double p[3]
    _geometry_face_ok(frames, face)
    dggs_ivea_inverse_unit(&frames[0, 0, 0], <int>face, x, y, p)
    return p[0], p[1], p[2]


# ---- Split (2:6) on a face plane (kernel.py) ----

def level1_digit(double x, double y):
    """Planar azimuth // 60 degrees by half-planes; the centre gives 0 (kernel.level1_digit)."""
    return dggs_level1_digit(x, y)


def level1_start(double x, double y):
    """``(digit, px, py)``: the level-1 digit and the point in that triangle's canonical frame (kernel.level1_start)."""
    cdef double px, py
    cdef int d = dggs_level1_start(x, y, &px, &py)
    return d, px, py


def descend(double px, double py):
    """``(digit, px, py)``: one level down in the canonical frame (kernel.descend)."""
    cdef int c = dggs_descend(&px, &py)
    return c, px, py


def descend4(double px, double py):
    """``(packed, px, py)``: four levels down at once, digit codes packed 2 bits each (kernel.descend4)."""
    cdef uint64_t packed = dggs_descend4(&px, &py)
    return packed, px, py


def child_corners(double ax, double ay, double bx, double by, double cx, double cy, Py_ssize_t digit):
    """Corners ``(ax, ay, bx, by, cx, cy)`` of child ``digit`` of the 30-60-90 triangle (kernel.child_corners)."""
    cdef double t[6]
    t[0] = ax
    t[1] = ay
    t[2] = bx
    t[3] = by
    t[4] = cx
    t[5] = cy
    dggs_child_corners(t, <int>digit)
    return t[0], t[1], t[2], t[3], t[4], t[5]


# ---- batch loops of the checked API (kernel.face_loops): any orientation's centres and frames ----

cdef inline int _geometry_forward_one(int ivea, const double *centres, const double *frames, double lat, double lng,
                                      double *x, double *y) noexcept nogil:
    cdef double cl = dggs_cos(lat), sl = dggs_sin(lat)
    if ivea:
        return dggs_ivea_forward_unit(centres, frames, cl * dggs_cos(lng), cl * dggs_sin(lng), sl, x, y)
    return dggs_snyder_forward_unit(centres, frames, cl * dggs_cos(lng), cl * dggs_sin(lng), sl, x, y)


cdef inline void _geometry_inverse_one(int ivea, const double *frames, int64_t nf, int64_t face, double x, double y,
                                       double *lat, double *lng) noexcept nogil:
    cdef double p[3]
    if face < 0 or face >= nf:  # not a face of these frames: numba would read past them
        lat[0] = NAN
        lng[0] = NAN
        return
    if ivea:
        dggs_ivea_inverse_unit(frames, <int>face, x, y, p)
    else:
        dggs_snyder_inverse_unit(frames, <int>face, x, y, p)
    lat[0] = dggs_atan2(p[2], dggs_hypot(p[0], p[1])) * DGGS_DEG_PER_RAD
    lng[0] = dggs_atan2(p[1], p[0]) * DGGS_DEG_PER_RAD


cdef int _geometry_forward_rad(int ivea, Py_ssize_t n, const double[:] lat, const double[:] lng,
                               const double[:, ::1] centres, const double[:, :, ::1] frames, int64_t[:] face,
                               double[:] x, double[:] y) except -1:
    cdef Py_ssize_t i, m = lat.shape[0]
    _geometry_centres_ok(centres)
    _geometry_face_ok(frames, 19)
    if lng.shape[0] < m or face.shape[0] < m or x.shape[0] < m or y.shape[0] < m:
        raise ValueError("forward_rad: lng, face, x and y must be at least as long as lat")
    cdef const double *c = &centres[0, 0]
    cdef const double *f = &frames[0, 0, 0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        face[i] = _geometry_forward_one(ivea, c, f, lat[i], lng[i], &x[i], &y[i])
    return 0


cdef int _geometry_inverse_deg(int ivea, Py_ssize_t n, const int64_t[:] face, const double[:] x, const double[:] y,
                               const double[:, :, ::1] frames, double[:] lat, double[:] lng) except -1:
    cdef Py_ssize_t i, m = face.shape[0]
    _geometry_frames_ok(frames)
    if x.shape[0] < m or y.shape[0] < m or lat.shape[0] < m or lng.shape[0] < m:
        raise ValueError("inverse_deg: x, y, lat and lng must be at least as long as face")
    cdef const double *f = &frames[0, 0, 0] if frames.shape[0] > 0 else NULL
    cdef int64_t nf = frames.shape[0]
    for i in prange(m, nogil=True, num_threads=_nthreads(n), schedule='static'):
        _geometry_inverse_one(ivea, f, nf, face[i], x[i], y[i], &lat[i], &lng[i])
    return 0


def snyder_forward_rad(Py_ssize_t n, const double[:] lat, const double[:] lng, const double[:, ::1] centres,
                       const double[:, :, ::1] frames, int64_t[:] face, double[:] x, double[:] y):
    """Snyder's forward of radian ``(lat, lng)`` on the sphere into ``face``, ``x``, ``y`` (kernel.forward_rad)."""
    _geometry_forward_rad(0, n, lat, lng, centres, frames, face, x, y)


def snyder_inverse_deg(Py_ssize_t n, const int64_t[:] face, const double[:] x, const double[:] y,
                       const double[:, :, ::1] frames, double[:] lat, double[:] lng):
    """Snyder's inverse of face-frame points into spherical ``(lat, lng)`` degrees (kernel.inverse_deg)."""
    _geometry_inverse_deg(0, n, face, x, y, frames, lat, lng)


def ivea_forward_rad(Py_ssize_t n, const double[:] lat, const double[:] lng, const double[:, ::1] centres,
                     const double[:, :, ::1] frames, int64_t[:] face, double[:] x, double[:] y):
    """IVEA's forward of radian ``(lat, lng)`` on the sphere into ``face``, ``x``, ``y`` (ivea.forward_rad)."""
    _geometry_forward_rad(1, n, lat, lng, centres, frames, face, x, y)


def ivea_inverse_deg(Py_ssize_t n, const int64_t[:] face, const double[:] x, const double[:] y,
                     const double[:, :, ::1] frames, double[:] lat, double[:] lng):
    """IVEA's inverse of face-frame points into spherical ``(lat, lng)`` degrees (ivea.inverse_deg)."""
    _geometry_inverse_deg(1, n, face, x, y, frames, lat, lng)
