// SceneSwitches.cpp - the scene's iSceneSwitches: what the step leaves out when a feature is off.
#include "PhysicsScene.h"

#include "RigidBody.h"

#include "iUtilities.h"

namespace physics {

bool PhysicsScene::setFeatureEnabled(SceneFeature f, bool on) {
    SolverSettings s = m_solver.settings();
    switch (f) {
    case FEATURE_Gravity: // a body asleep under the old field would hang in the new one
        if (on != m_gravityOn)
            for (RigidBody* b : bodies()) b->wake();
        m_gravityOn = on;
        break;
    case FEATURE_Drag:
        m_dragOn = on;
        break;
    case FEATURE_Friction:
        s.frictionOn = on;
        break;
    case FEATURE_Restitution:
        s.restitutionOn = on;
        break;
    case FEATURE_ContinuousCollision:
        m_continuousOn = on;
        break;
    case FEATURE_Sleeping:
        setSleepingEnabled(on);
        break;
    case FEATURE_Listeners:
        m_listenersOn = on;
        break;
    case FEATURE_Validation:
        m_validationOn = on;
        break;
    case FEATURE_Interpolation:
        m_interpolationOn = on;
        break;
    default:
        error(L"iSceneSwitches::setFeatureEnabled: not a SceneFeature; refused");
        return false;
    }
    m_solver.setSettings(s);
    return true;
}

bool PhysicsScene::isFeatureEnabled(SceneFeature f) const {
    switch (f) {
    case FEATURE_Gravity:
        return m_gravityOn;
    case FEATURE_Drag:
        return m_dragOn;
    case FEATURE_Friction:
        return m_solver.settings().frictionOn;
    case FEATURE_Restitution:
        return m_solver.settings().restitutionOn;
    case FEATURE_ContinuousCollision:
        return m_continuousOn;
    case FEATURE_Sleeping:
        return m_sleeping;
    case FEATURE_Listeners:
        return m_listenersOn;
    case FEATURE_Validation:
        return m_validationOn;
    case FEATURE_Interpolation:
        return m_interpolationOn;
    default:
        return false;
    }
}

} // namespace physics
