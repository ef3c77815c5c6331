"""LoopAdder plugins: loops of the walkable graph added back to the Steiner forest (optional stage after step 3)."""
