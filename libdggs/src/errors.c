/* Error descriptions (dggs.h). */
#include "dggs.h"

const char *dggs_error_string(dggs_error err) {
    switch (err) {
        case DGGS_OK: return "success";
        case DGGS_E_LATLNG: return "latitude outside -90..90 or coordinate not finite";
        case DGGS_E_LEVEL: return "level outside 0..28";
        case DGGS_E_CELL: return "not a cell id";
        case DGGS_E_LEVEL_MISMATCH: return "cell at the wrong level for the operation";
        case DGGS_E_BUFFER: return "output buffer too small";
        case DGGS_E_DOMAIN: return "argument out of its domain";
        case DGGS_E_FAILED: return "operation could not complete";
        case DGGS_E_PROJECTION: return "not a projection";
        case DGGS_E_EDGE: return "not a directed edge id";
        case DGGS_E_VERTEX: return "not a vertex id";
    }
    return "unknown error";
}
