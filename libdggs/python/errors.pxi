# Error codes and their descriptions (dggs.h).

cdef extern from "dggs.h" nogil:
    const char *dggs_error_string(int err)


def error_string(int err):
    """The core's description of error code ``err``."""
    return dggs_error_string(err).decode()
