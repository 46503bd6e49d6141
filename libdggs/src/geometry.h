/* The geometry floor of the core: the authalic sphere, Snyder's (ISEA) and the IVEA projection per point, and
 * the Split (2:6) steps on a face plane. A port of dggs/geometry/kernel.py and ivea.py, operation for
 * operation (the ids must equal the Python kernel's bit for bit).
 *
 * Tables (tables.h, written by tools/gen_tables.py from the Python geometry floor) hold PROJ's ISEA
 * orientation, the authalic series and the Split (2:6) matrices and jump table.
 *
 * Python names: kernel.X is dggs_X, except kernel.face_forward / forward_unit / inverse_unit, which are
 * dggs_snyder_face_forward / dggs_snyder_forward_unit / dggs_snyder_inverse_unit; ivea.face_forward /
 * forward_unit / face_inverse / natural_forward / natural_inverse are dggs_ivea_face_forward /
 * dggs_ivea_forward_unit / dggs_ivea_inverse_unit / dggs_ivea_natural_forward / dggs_ivea_natural_inverse.
 * `face` must be 0..19 (not checked here; the public dggs_face_to_geo checks it). Pure functions of their
 * arguments and static const tables: thread-safe. */
#ifndef DGGS_GEOMETRY_H
#define DGGS_GEOMETRY_H

#include <stdint.h>

#include "dggs.h"
#include "faces.h"

/* A longitude reduced exactly to -180..180 (fmod is exact; no radians first). */
double dggs_wrap_degrees(double lng);
/* Vector on the authalic sphere (any norm) -> geodetic WGS84 (lat, lng) degrees. */
void dggs_unit_to_geodetic(double px, double py, double pz, double *lat, double *lng);
/* (sin beta, cos beta) of the authalic latitude from the geodetic one's sin and cos. */
void dggs_authalic_sincos(double sp, double cp, double *sb, double *cb);
/* Geodetic WGS84 degrees -> unit vector on the authalic sphere. */
void dggs_geodetic_to_unit(double lat, double lng, double p[3]);

/* Snyder's forward and inverse in any orientation: `centres` is (20, 3), `frames` (20, 3, 3), row-major.
 * dggs_nearest_face and dggs_sector_of, shared with IVEA, are in faces.h. */
/* Snyder's forward inside one 120-degree sector: (rho sin Az', rho cos Az') (kernel.sector_forward). */
void dggs_sector_forward(double sin_az, double cos_az, double sin_half_z, double *x, double *y);
void dggs_snyder_face_forward(const double *frames, int face, double px, double py, double pz, double *x, double *y);
int dggs_snyder_forward_unit(const double *centres, const double *frames, double px, double py, double pz, double *x,
                             double *y);
void dggs_snyder_inverse_unit(const double *frames, int face, double x, double y, double p[3]);
/* Most points dggs_snyder_inverse_units takes at once (a cell's boundary for the points per edge: 12). */
#define DGGS_INVERSE_LANES 12
/* dggs_snyder_inverse_unit of n <= DGGS_INVERSE_LANES points (x[j], y[j]) of one face into p[j], faster (their chains
 * overlap); dggs_snyder_inverse_unit is this with n = 1. */
void dggs_snyder_inverse_units(const double *frames, int face, int n, const double *x, const double *y,
                               double (*p)[3]);
/* IVEA's, the same signatures (dggs/geometry/ivea.py). */
void dggs_ivea_face_forward(const double *frames, int face, double px, double py, double pz, double *x, double *y);
int dggs_ivea_forward_unit(const double *centres, const double *frames, double px, double py, double pz, double *x,
                           double *y);
void dggs_ivea_inverse_unit(const double *frames, int face, double x, double y, double p[3]);
/* IVEA's map of the natural triangle (ivea.natural_forward / natural_inverse): unit (c, n, e) <-> planar (x, y). */
void dggs_ivea_natural_forward(double c, double n, double e, double *x, double *y);
void dggs_ivea_natural_inverse(double x, double y, double p[3]);

/* The standard grid (PROJ's ISEA orientation) on either projection: unit vector -> face and face-frame (x, y)
 * (the face returned), the same for a given face, and face-frame (x, y) -> unit vector. */
int dggs_proj_forward(dggs_projection proj, double px, double py, double pz, double *x, double *y);
void dggs_proj_face_forward(dggs_projection proj, int face, double px, double py, double pz, double *x, double *y);
void dggs_proj_inverse(dggs_projection proj, int face, double x, double y, double p[3]);
/* dggs_proj_inverse of n points of one face, p[j] from (x[j], y[j]): the same bits, several at once on ISEA. */
void dggs_proj_inverse_many(dggs_projection proj, int face, int n, const double *x, const double *y, double (*p)[3]);

/* Planar azimuth // 60 degrees by half-planes; the centre gives 0. */
int dggs_level1_digit(double x, double y);
/* Level-1 digit and the point in that triangle's canonical frame (*px, *py). */
int dggs_level1_start(double x, double y, double *px, double *py);
/* One level down in the canonical frame: the child digit; the point moves into the child's frame. */
int dggs_descend(double *px, double *py);
/* Four levels down: packed digit codes (8 bits, first level highest); the point moves. */
uint64_t dggs_descend4(double *px, double *py);
/* Corners (A, B, C) of child `digit` of the 30-60-90 triangle t = (ax, ay, bx, by, cx, cy), in place. */
void dggs_child_corners(double t[6], int digit);

#endif
