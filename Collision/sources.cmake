# The collision detector's files, relative to Collision/ (also read by the package generator).
set(GUARDIAN_COLLISION_SOURCES)
set(GUARDIAN_COLLISION_HEADERS)
list(TRANSFORM GUARDIAN_COLLISION_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
