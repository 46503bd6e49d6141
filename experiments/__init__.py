"""Reproductions of the thesis's experiments (chapters 4-7): research code beside the library.

The top-level folder ``experiments/``, installed as ``dggs.experiments``; ``import dggs`` loads none of it.
"""
