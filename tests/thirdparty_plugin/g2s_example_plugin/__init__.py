"""An example third-party g2s plugin package."""
