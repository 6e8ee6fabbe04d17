"""The physical model of a scene: bodies, shapes and inertia, supports, loads."""
