"""The geometry kernel: icosahedron, authalic latitude, Snyder's projection, Split (2:6) planes.

Knows no cell ids and no database: faces, planar face frames and digits only.
"""
