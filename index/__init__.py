"""Cell addressing (installed as ``dggs.index``): ids, point-to-cell, hierarchy, neighbours, polyfill.

The public names are re-exported from :mod:`dggs`; import them from there.
"""
