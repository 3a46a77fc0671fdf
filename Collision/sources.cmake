# The collision detector's files, relative to Collision/ (also read by the package generator).
set(GUARDIAN_COLLISION_SOURCES
  CollideSphereSphere.cpp CollideSphereBox.cpp CollideBoxBox.cpp CollidePlane.cpp Dispatch.cpp Queries.cpp
  CollisionGeometry.cpp CSphere.cpp COBB.cpp CPlane.cpp CCompound.cpp
  SimpleCollisionSpace.cpp SpaceNarrowPhase.cpp SpaceListeners.cpp SpaceEvents.cpp SpaceContactEvents.cpp SpaceQueries.cpp SpaceQueryBatch.cpp
  SeparationBound.cpp SpaceShapeCast.cpp SpaceCastObstacles.cpp SpaceSnapshot.cpp DynamicTree.cpp SweepAndPrune.cpp TreeBroadphase.cpp
  SpaceDebugDraw.cpp SpaceWake.cpp SpaceGather.cpp SpaceLayout.cpp)
set(GUARDIAN_COLLISION_HEADERS
  Shapes.h BoxAxes.h FetchAhead.h VectorRegister.h PoseInputs.h Narrowphase.h ManifoldReduce.h CollisionGeometry.h SpaceEntry.h SimpleCollisionSpace.h Broadphase.h
  DynamicTree.h SweepAndPrune.h TreeBroadphase.h GrowingArrays.h)
list(TRANSFORM GUARDIAN_COLLISION_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
