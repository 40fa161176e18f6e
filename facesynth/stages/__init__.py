"""Pipeline stages. Each module has a pure core working on arrays and a thin ``run`` that
reads its input artifact, calls the core and writes its output artifact.
"""
