"""Built-in g2s plugins, one sub-package per stage (see g2s_core.plugin)."""
