# The simulator's files, relative to Physics/ (also read by the package generator).
set(GUARDIAN_PHYSICS_SOURCES)
set(GUARDIAN_PHYSICS_HEADERS)
list(TRANSFORM GUARDIAN_PHYSICS_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
