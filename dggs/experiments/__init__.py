"""Reproductions of the thesis's experiments (chapters 4-6)."""
