/* A polyline's points checked and its anchors laid out: a port of index/_kernel/line_layout.py. */
#include "line_layout.h"

#include <math.h>

int64_t dggs_span_count(double q) {
    double c = ceil(q);
    /* numba's int(math.ceil(q)) is fptosi: in range it truncates (exact on an integral value); out of range,
     * or NaN, x86-64 gives INT64_MIN, which max(1, .) turns into 1 */
    int64_t m = (c >= -9223372036854775808.0 && c < 9223372036854775808.0) ? (int64_t)c : INT64_MIN;
    return m > 1 ? m : 1;
}

int64_t dggs_clean(const double *xy, size_t n, double *out, size_t *count) {
    *count = 0;
    for (size_t i = 0; i < n; i++) {
        double la = xy[2 * i], lo = xy[2 * i + 1];
        if (!(-90.0 <= la && la <= 90.0) || !isfinite(lo)) return (int64_t)i;
    }
    /* every point checked first, as the numba loop returns before writing; then the kept points in order
     * (in place when out is xy: the write index never passes the read index) */
    size_t j = 0;
    double pla = 0.0, plo = 0.0;
    for (size_t i = 0; i < n; i++) {
        double la = xy[2 * i], lo = xy[2 * i + 1];
        if (i == 0 || la != pla || lo != plo) {
            out[2 * j] = la;
            out[2 * j + 1] = lo;
            j++;
        }
        pla = la;
        plo = lo;
    }
    *count = j;
    return -1;
}

void dggs_layout_size(const double *dist, size_t nseg, double max_span, size_t *size, size_t *inner) {
    size_t sz = 1, in = 0;
    for (size_t i = 0; i < nseg; i++) {
        int64_t m = dggs_span_count(dist[i] / max_span);
        sz += (size_t)m;
        in += (size_t)(m - 1);
    }
    *size = sz;
    *inner = in;
}

void dggs_layout(const double *xy, const double *az12, const double *az21, const double *dist, size_t nseg,
                 double max_span, double *lat, double *lng, double *az_out, double *az_in, double *span, int64_t *at,
                 int64_t *seg, double *s) {
    size_t size, inner;
    dggs_layout_size(dist, nseg, max_span, &size, &inner);
    for (size_t k = 0; k < size; k++) {
        az_out[k] = 0.0;
        az_in[k] = 0.0;
    }
    size_t k = 0, r = 0;
    for (size_t i = 0; i < nseg; i++) {
        int64_t m = dggs_span_count(dist[i] / max_span);
        lat[k] = xy[2 * i];
        lng[k] = xy[2 * i + 1];
        az_out[k] = az12[i];
        double step = dist[i] / (double)m;
        for (int64_t j = 0; j < m; j++) {
            span[k + (size_t)j] = step;
            if (j > 0 && at != NULL) { /* at, seg and s are optional (NULL: the caller fills the anchors itself) */
                at[r] = (int64_t)(k + (size_t)j);
                seg[r] = (int64_t)i;
                s[r] = (double)j * step;
                r++;
            }
        }
        k += (size_t)m;
        az_in[k] = az21[i] + 180.0;
    }
    lat[k] = xy[2 * nseg];
    lng[k] = xy[2 * nseg + 1];
}
