# grid: filled in by its port (see core.pyx).
