// Tracking.cpp - finding the tracked bodies and printing where they are.
#include "Tracking.h"

#include "MathDefinitions.h"
#include "RBDynamics.h"
#include "World.h"
#include "iPhysicsFrame.h"

#include <cstdlib>

void BodyTracker::resolve(const World& world, const std::vector<std::string>& wanted, const char* scene,
                          std::FILE* err) {
    for (const std::string& w : wanted) {
        const iPhysicsFrame* body = world.named(w);
        if (!body && !w.empty() && w.find_first_not_of("0123456789") == std::string::npos) {
            unsigned long i = std::strtoul(w.c_str(), nullptr, 10);
            if (i < world.bodies().size()) body = world.bodies()[i];
        }
        if (body) {
            m_names.push_back(w);
            m_bodies.push_back(body);
            continue;
        }
        std::fprintf(err, "--track: scene %s has no body '%s' (named:", scene, w.c_str());
        for (const auto& n : world.names()) std::fprintf(err, " %s", n.first.c_str());
        std::fprintf(err, "%s; or an index below %zu)\n", world.names().empty() ? " none" : "",
                     world.bodies().size());
    }
}

std::vector<Vector> BodyTracker::positions() const {
    std::vector<Vector> out;
    for (const iPhysicsFrame* b : m_bodies) out.push_back(b->getDynamics()->position);
    return out;
}

void BodyTracker::print(std::FILE* out) const {
    for (size_t i = 0; i < m_bodies.size(); ++i) {
        const RBDynamics* d = m_bodies[i]->getDynamics();
        std::fprintf(out, "  track %-8s pos (%8.3f, %8.3f, %8.3f) m  speed %7.3f m/s%s\n", m_names[i].c_str(),
                     d->position.x, d->position.y, d->position.z, d->velocity.length(),
                     d->sleeping ? "  asleep" : "");
    }
}
