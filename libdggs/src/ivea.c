/* The vertex-oriented great circle projection of the icosahedron (IVEA), per point: a transliteration of the
 * compiled part of dggs/geometry/ivea.py, operation for operation.
 *
 * van Leeuwen, D. and Strebe, D. (2006), "A 'Slice-and-Dice' approach to area equivalence in polyhedral map
 * projections", Cartography and Geographic Information Science 33(4): 269-286; thesis §3.1.5 and §3.1.7.
 * The map works on the natural triangle V (face vertex), C (face centre), M (edge midpoint): the slice
 * A(rho) = rho - asin(cos VM sin rho), the dice |V'P'| / |V'D'| = sin(VP / 2) / sin(VD / 2) with
 * tan VD = tan VM / cos rho; the inverse is closed-form, tan rho = sin A / (cos A - cos VM) (docs/grid.md,
 * "The IVEA projection"). The same faces, face frames and planar triangles as Snyder's (geometry.c). */
#include <math.h>

#include "dmath.h"
#include "faces.h"
#include "geometry.h"
#include "tables.h"

/* ivea.natural_forward: unit vector (c, n, e) in the natural triangle (azimuth 0..60) -> planar (x, y). */
void dggs_ivea_natural_forward(double c, double n, double e, double *x, double *y) {
    double det = DGGS_IVEA_VX * (DGGS_IVEA_MY * e - DGGS_IVEA_MZ * n) - DGGS_IVEA_VY * (DGGS_IVEA_MX * e - DGGS_IVEA_MZ * c) +
                 DGGS_IVEA_VZ * (DGGS_IVEA_MX * n - DGGS_IVEA_MY * c);
    double sin_part = DGGS_IVEA_SGN * det; /* |V x M| |V x P| sin rho */
    double cos_part = DGGS_IVEA_MX * c + DGGS_IVEA_MY * n + DGGS_IVEA_MZ * e -
                      (DGGS_IVEA_VX * c + DGGS_IVEA_VY * n + DGGS_IVEA_VZ * e) * DGGS_IVEA_VM; /* ... cos rho */
    double h = dggs_hypot(sin_part, cos_part);
    if (h == 0.0) { /* P = V (or its antipode) */
        *x = 0.0;
        *y = DGGS_IVEA_RV;
        return;
    }
    double rho = dggs_atan2(sin_part, cos_part);
    double cos_rho = cos_part / h;
    double area = rho - dggs_asin(DGGS_IVEA_COS_VM * (sin_part / h)); /* rho + delta - pi / 2, delta by Napier */
    double cos_vd = cos_rho / sqrt(cos_rho * cos_rho + DGGS_IVEA_TAN_VM2); /* tan VD = tan VM / cos rho */
    double dc = c - DGGS_IVEA_VX, dn = n - DGGS_IVEA_VY, de = e - DGGS_IVEA_VZ;
    double half_vp = 0.5 * sqrt(dc * dc + dn * dn + de * de); /* sin(VP / 2) */
    double s = half_vp / sqrt(0.5 * (1.0 - cos_vd));         /* the dice: |V'P'| / |V'D'| */
    double t = area / DGGS_IVEA_NATURAL_AREA;                /* the slice: |M'D'| / |M'C'| */
    double dx = (1.0 - t) * DGGS_IVEA_RM * DGGS_IVEA_H, dy = (1.0 - t) * DGGS_IVEA_RM * 0.5;
    *x = s * dx;
    *y = DGGS_IVEA_RV + s * (dy - DGGS_IVEA_RV);
}

/* ivea.natural_inverse: planar (x, y) in the natural triangle -> unit vector (c, n, e), closed form. */
void dggs_ivea_natural_inverse(double x, double y, double p[3]) {
    double qx = x, qy = y - DGGS_IVEA_RV;
    double s = (0.5 * qx - DGGS_IVEA_H * qy) / (DGGS_IVEA_H * DGGS_IVEA_RV); /* V' + q / s lies on M'C' */
    if (s <= DGGS_TINY) {
        p[0] = DGGS_IVEA_VX;
        p[1] = DGGS_IVEA_VY;
        p[2] = DGGS_IVEA_VZ;
        return;
    }
    double lam = (qx / s) * DGGS_IVEA_H + (DGGS_IVEA_RV + qy / s) * 0.5; /* |C'D'| */
    double area = (1.0 - lam / DGGS_IVEA_RM) * DGGS_IVEA_NATURAL_AREA;
    double sin_a, cos_a;
    dggs_sincos(area, &sin_a, &cos_a);
    double rho = dggs_atan2(sin_a, cos_a - DGGS_IVEA_COS_VM); /* tan rho = sin A / (cos A - cos VM) */
    double sin_rho, cos_rho;
    dggs_sincos(rho, &sin_rho, &cos_rho);
    double cos_vd = cos_rho / sqrt(cos_rho * cos_rho + DGGS_IVEA_TAN_VM2);
    double half = s * sqrt(0.5 * (1.0 - cos_vd)); /* sin(VP / 2) */
    if (1.0 < half) half = 1.0;                   /* min(half, 1.0) as Python's */
    double cos_x = 1.0 - 2.0 * half * half;
    double sin_x = 2.0 * half * sqrt(1.0 - half * half);
    double a = sin_x * cos_rho, b = sin_x * sin_rho;
    p[0] = cos_x * DGGS_IVEA_VX + a * DGGS_IVEA_T0 + b * DGGS_IVEA_T3;
    p[1] = cos_x * DGGS_IVEA_VY + a * DGGS_IVEA_T1 + b * DGGS_IVEA_T4;
    p[2] = cos_x * DGGS_IVEA_VZ + a * DGGS_IVEA_T2 + b * DGGS_IVEA_T5;
}

/* ivea.face_forward: unit vector -> (x, y) in the frame of `face` (as kernel.face_forward, by IVEA). */
void dggs_ivea_face_forward(const double *frames, int face, double px, double py, double pz, double *x, double *y) {
    const double *f = frames + 9 * face;
    double c = f[0] * px + f[1] * py + f[2] * pz;
    double n = f[3] * px + f[4] * py + f[5] * pz;
    double e = f[6] * px + f[7] * py + f[8] * pz;
    int k = dggs_sector_of(e, n); /* the 120-degree sector by the azimuth of (east, north) */
    double rc = dggs_rot_cos[k], rs = dggs_rot_sin[k];
    double e1 = e * rc - n * rs, n1 = n * rc + e * rs; /* turned by -120 k degrees */
    e = e1;
    n = n1;
    int mirror = 0.5 * e - DGGS_IVEA_H * n > 0.0; /* azimuth past 60: the mirror image across azimuth 60 */
    if (mirror) {
        double n2 = -0.5 * n + DGGS_IVEA_H * e, e2 = DGGS_IVEA_H * n + 0.5 * e;
        n = n2;
        e = e2;
    }
    double xx, yy;
    dggs_ivea_natural_forward(c, n, e, &xx, &yy);
    if (mirror) {
        double y2 = -0.5 * yy + DGGS_IVEA_H * xx, x2 = DGGS_IVEA_H * yy + 0.5 * xx;
        yy = y2;
        xx = x2;
    }
    *x = xx * rc + yy * rs;
    *y = yy * rc - xx * rs;
}

/* ivea.forward_unit: unit vector -> (face, x, y): the nearest face (as kernel.forward_unit), then IVEA. */
int dggs_ivea_forward_unit(const double *centres, const double *frames, double px, double py, double pz, double *x,
                           double *y) {
    int face = dggs_nearest_face(centres, px, py, pz);
    dggs_ivea_face_forward(frames, face, px, py, pz, x, y);
    return face;
}

/* ivea.face_inverse: face-frame (x, y) -> unit vector (as kernel.inverse_unit, by IVEA). */
void dggs_ivea_inverse_unit(const double *frames, int face, double x, double y, double p[3]) {
    int k = dggs_sector_of(x, y);
    double rc = dggs_rot_cos[k], rs = dggs_rot_sin[k];
    double x1 = x * rc - y * rs, y1 = y * rc + x * rs;
    x = x1;
    y = y1;
    int mirror = 0.5 * x - DGGS_IVEA_H * y > 0.0;
    if (mirror) {
        double y2 = -0.5 * y + DGGS_IVEA_H * x, x2 = DGGS_IVEA_H * y + 0.5 * x;
        y = y2;
        x = x2;
    }
    double q[3];
    dggs_ivea_natural_inverse(x, y, q);
    double c = q[0], n = q[1], e = q[2];
    if (mirror) {
        double n2 = -0.5 * n + DGGS_IVEA_H * e, e2 = DGGS_IVEA_H * n + 0.5 * e;
        n = n2;
        e = e2;
    }
    double n3 = n * rc - e * rs, e3 = e * rc + n * rs;
    n = n3;
    e = e3;
    const double *f = frames + 9 * face;
    p[0] = c * f[0] + n * f[3] + e * f[6];
    p[1] = c * f[1] + n * f[4] + e * f[7];
    p[2] = c * f[2] + n * f[5] + e * f[8];
}
