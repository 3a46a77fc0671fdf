// main.cpp - the reference game's entry point: a headless run of the course engine loop.
//
// Usage: ReferenceGame [--scene NAME] [--frames N]
// Until the simulator and the collision detector land there is no scene to run: it says so and exits 0.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
    std::string scene = "none";
    int frames = 600;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--scene") && i + 1 < argc)
            scene = argv[++i];
        else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            frames = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: ReferenceGame [--scene NAME] [--frames N]\n");
            return 2;
        }
    }
    std::printf("ReferenceGame: scene '%s', %d frames requested: no scene exists yet (the simulator has not "
                "landed)\n",
                scene.c_str(), frames);
    return 0;
}
