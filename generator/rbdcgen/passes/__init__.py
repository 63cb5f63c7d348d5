"""From algorithms to traced functions: the function tables, tracing, differentiation, projection onto couplings."""
