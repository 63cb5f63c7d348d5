"""The expression graph, its folding, spatial algebra over symbols, the manifold, operation counts."""
