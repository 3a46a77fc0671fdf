# The simulator's files, relative to Physics/ (also read by the package generator).
set(GUARDIAN_PHYSICS_SOURCES
  BodyMotion.cpp
  BodyValidation.cpp
  Composite.cpp
  FrameDriver.cpp
  ContactManifolds.cpp
  ContactResolution.cpp
  ContactRestitution.cpp
  ContactSolver.cpp
  ContinuousStage.cpp
  Integrators.cpp
  PhysicsFrame.cpp
  PhysicsScene.cpp
  PhysicsSceneContacts.cpp SceneSnapshot.cpp
  SceneLifetime.cpp
  WorldPoseCache.cpp
  RigidBody.cpp
  SceneDebugDraw.cpp
  SceneSwitches.cpp
  ShockPropagation.cpp)
set(GUARDIAN_PHYSICS_HEADERS
  BodyValidation.h
  Composite.h
  FrameDriver.h
  ContactManifold.h
  ContactResolution.h
  ContactSolver.h
  SolverRows.h
  ContinuousStage.h
  Integrators.h
  MathBridge.h
  PhysicsScene.h
  RigidBody.h)
list(TRANSFORM GUARDIAN_PHYSICS_SOURCES PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
