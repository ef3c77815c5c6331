"""SteinerSolver plugins: Kou et al. (1981) and Mehlhorn (1988) 2-approximations on scipy's csgraph."""
