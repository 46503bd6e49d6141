"""Cell addressing (installed as ``dggs.index``): ids, point-to-cell, hierarchy, neighbours, polyfill.

The public names are re-exported from :mod:`dggs`; import them from there.
"""

if __name__ != "dggs.index":  # the numba cache records module names: one name per file
    raise ImportError("import this package as dggs.index (it is installed under that name), not as 'index'")
