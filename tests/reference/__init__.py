"""Reference data (fixtures/) and independent numpy oracles of the compiled kernel."""
