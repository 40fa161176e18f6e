"""The base layer: errors, settings, limits, phone sets, OpenCL, progress, hashing and the stage
declarations. It imports nothing of facesynth above it; nothing here reads an artifact."""
