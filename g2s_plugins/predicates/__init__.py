"""SimplifyPredicate plugins: decide whether B may be removed from a chain A -> B -> C (Algorithm 4)."""
