// Screenshot.h - the window's picture as a file: the OpenGL framebuffer read back and written as a binary
// PPM (P6: no dependency) or, when the name ends in .png, a PNG (stb_image_write, which Debian's imgui
// package already depends on).
#pragma once

#include <string>

// Reads width x height pixels of the current context's back buffer (call before swapping buffers) and
// writes them to path, top row first. False (and a message on stderr) when the file cannot be written.
bool writeScreenshot(const std::string& path, int width, int height);
