"""The parts of bench/report: shared names and formatting (common), building and running the
programs (runner), the derivatives (derivatives) and the run-time-against-error plot (plot)."""
