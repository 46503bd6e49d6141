/* The dggs DuckDB extension's entry point: registers each function file's functions (ext.h). */
#include "ext.h"

DUCKDB_EXTENSION_ENTRYPOINT(duckdb_connection connection, duckdb_extension_info info,
                            struct duckdb_extension_access *access) {
    (void)info;
    (void)access;
    register_cells(connection);
    register_grid(connection);
    register_edges(connection);
    register_fill(connection);
    register_levels(connection);
    register_vertex(connection);
    register_dissolve(connection);
    return true;
}
