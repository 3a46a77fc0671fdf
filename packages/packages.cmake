# The three drop-in packages of the seed: which modules each one carries. The files themselves are computed
# (scripts/make_package.cmake): the module's own sources plus every Interfaces/ header they include,
# transitively. Nothing else, so collision-only has no Physics/ file and sim-only no Collision/ file.
set(GUARDIAN_PACKAGES sim-collision sim-only collision-only)
set(GUARDIAN_PACKAGE_sim-collision_MODULES Physics Collision)
set(GUARDIAN_PACKAGE_sim-only_MODULES Physics)
set(GUARDIAN_PACKAGE_collision-only_MODULES Collision)
