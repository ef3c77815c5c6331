"""GraphBuilder plugins: build the initial surface graph from a triangle mesh."""
