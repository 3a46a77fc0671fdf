// Screenshot.cpp - reading the framebuffer back and writing it as PPM or PNG (Screenshot.h).
#include "Screenshot.h"

#include <GL/gl.h>
#include <stb_image_write.h>

#include <cstdio>
#include <vector>

bool writeScreenshot(const std::string& path, int width, int height) {
    if (width <= 0 || height <= 0) return false;
    std::vector<unsigned char> bottomUp(size_t(width) * size_t(height) * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    // OpenGL's rows start at the bottom; image files start at the top.
    const size_t row = size_t(width) * 3;
    std::vector<unsigned char> pixels(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::copy(bottomUp.begin() + long(size_t(height - 1 - y) * row),
                  bottomUp.begin() + long(size_t(height - y) * row), pixels.begin() + long(size_t(y) * row));
    const bool png = path.size() > 4 && path.compare(path.size() - 4, 4, ".png") == 0;
    bool ok = false;
    if (png) {
        ok = stbi_write_png(path.c_str(), width, height, 3, pixels.data(), int(row)) != 0;
    } else if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fprintf(f, "P6\n%d %d\n255\n", width, height);
        ok = std::fwrite(pixels.data(), 1, pixels.size(), f) == pixels.size();
        ok = std::fclose(f) == 0 && ok;
    }
    if (!ok) std::fprintf(stderr, "Testbed: cannot write %s\n", path.c_str());
    return ok;
}
