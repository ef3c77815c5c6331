"""RootSelector plugins: score the nodes of the Steiner forest; each tree is rooted at its best node."""
