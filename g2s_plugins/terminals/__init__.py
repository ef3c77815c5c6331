"""TerminalSelector plugins: choose the nodes the structure must join (the paper's step 2)."""
