"""Motion-node search: the cost terms of paper VI-B and the dynamic program of Algorithm 1."""
