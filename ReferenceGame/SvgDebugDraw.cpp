// SvgDebugDraw.cpp - collecting the engine's drawing and writing it as an SVG picture (SvgDebugDraw.h).
#include "SvgDebugDraw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>

namespace {

// The SVG paint of a packed 0xAARRGGBB colour: attribute="#RRGGBB", plus its opacity unless opaque (most
// colours are: leaving it out keeps the files small).
std::string svgPaint(const char* attribute, DebugColour c) {
    char buffer[64];
    const unsigned alpha = (c >> 24) & 0xFFu;
    if (alpha == 0xFFu)
        std::snprintf(buffer, sizeof buffer, "%s=\"#%06X\"", attribute, unsigned(c & 0xFFFFFFu));
    else
        std::snprintf(buffer, sizeof buffer, "%s=\"#%06X\" %s-opacity=\"%.2f\"", attribute,
                      unsigned(c & 0xFFFFFFu), attribute, double(alpha) / 255.0);
    return buffer;
}

std::string svgEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else
            out += c;
    }
    return out;
}

} // namespace

SvgDebugDraw::SvgDebugDraw(int width, int height, const Vector& viewDirection, float margin)
    : m_width(width), m_height(height), m_margin(margin) {
    m_forward = viewDirection.normalize();
    // World y up on the page, unless the camera looks straight up or down: then world z is up.
    Vector worldUp = std::fabs(m_forward.y) > 0.999f ? Vector(0, 0, 1) : Vector(0, 1, 0);
    m_right = cross(worldUp, m_forward).normalize(); // left-handed: looking along +z, +x is right
    m_up = cross(m_forward, m_right);
}

void SvgDebugDraw::drawLine(const Vector& from, const Vector& to, DebugColour colour) {
    m_items.push_back({Item::Line, from, to, 0.0f, colour, std::string()});
}
void SvgDebugDraw::drawText(const Vector& at, const char* text, DebugColour colour) {
    m_items.push_back({Item::Text, at, at, 0.0f, colour, text ? text : ""});
}
void SvgDebugDraw::drawPoint(const Vector& at, float size, DebugColour colour) {
    m_items.push_back({Item::Dot, at, at, size * 0.5f, colour, std::string()});
}
void SvgDebugDraw::drawWireSphere(const Vector& centre, float radius, DebugColour colour) {
    m_items.push_back({Item::Circle, centre, centre, radius, colour, std::string()});
}

void SvgDebugDraw::clear() { m_items.clear(); }

float SvgDebugDraw::depth(const Item& item) const {
    return dot((item.a + item.b) * 0.5f, m_forward); // larger is farther from the camera
}

SvgDebugDraw::Fit SvgDebugDraw::fit() const {
    float lo[2] = {0, 0}, hi[2] = {0, 0};
    bool any = false;
    auto grow = [&](const Vector& p, float pad) {
        const float r = right(p), u = up(p);
        if (!any) {
            lo[0] = r - pad, hi[0] = r + pad, lo[1] = u - pad, hi[1] = u + pad;
            any = true;
            return;
        }
        lo[0] = std::min(lo[0], r - pad), hi[0] = std::max(hi[0], r + pad);
        lo[1] = std::min(lo[1], u - pad), hi[1] = std::max(hi[1], u + pad);
    };
    for (const Item& item : m_items) {
        grow(item.a, item.kind == Item::Circle || item.kind == Item::Dot ? item.size : 0.0f);
        if (item.kind == Item::Line) grow(item.b, 0.0f);
    }
    const float w = hi[0] - lo[0], h = hi[1] - lo[1];
    const float roomX = float(m_width) - 2 * m_margin, roomY = float(m_height) - 2 * m_margin;
    float scale = 1.0f; // nothing, or a single point: any scale centres it
    if (w > 0 && h > 0)
        scale = std::min(roomX / w, roomY / h);
    else if (w > 0)
        scale = roomX / w;
    else if (h > 0)
        scale = roomY / h;
    return Fit{lo[0], lo[1], scale, (float(m_width) - w * scale) * 0.5f,
               (float(m_height) - h * scale) * 0.5f};
}

SvgDebugDraw::Pixel SvgDebugDraw::toPixel(const Fit& f, const Vector& p) const {
    return Pixel{f.offsetX + (right(p) - f.minRight) * f.scale,
                 float(m_height) - f.offsetY - (up(p) - f.minUp) * f.scale};
}

SvgDebugDraw::Pixel SvgDebugDraw::project(const Vector& p) const { return toPixel(fit(), p); }

std::string SvgDebugDraw::svg() const {
    const Fit f = fit();
    // Painter's order: far to near; equal depths keep the order they were drawn in.
    std::vector<size_t> order(m_items.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t i, size_t j) { return depth(m_items[i]) > depth(m_items[j]); });
    std::string out;
    char buffer[256];
    std::snprintf(
        buffer, sizeof buffer,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n"
        "<rect width=\"100%%\" height=\"100%%\" fill=\"#FFFFFF\"/>\n",
        m_width, m_height, m_width, m_height);
    out += buffer;
    for (size_t index : order) {
        const Item& item = m_items[index];
        const Pixel a = toPixel(f, item.a);
        const std::string stroke = svgPaint("stroke", item.colour), fill = svgPaint("fill", item.colour);
        switch (item.kind) {
        case Item::Line: {
            const Pixel b = toPixel(f, item.b);
            std::snprintf(buffer, sizeof buffer,
                          "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>\n", double(a.x),
                          double(a.y), double(b.x), double(b.y), stroke.c_str());
            break;
        }
        case Item::Dot:
            std::snprintf(buffer, sizeof buffer, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" %s/>\n",
                          double(a.x), double(a.y), double(std::max(1.5f, item.size * f.scale)),
                          fill.c_str());
            break;
        case Item::Circle:
            std::snprintf(buffer, sizeof buffer,
                          "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" %s/>\n", double(a.x),
                          double(a.y), double(item.size * f.scale), stroke.c_str());
            break;
        case Item::Text:
            std::snprintf(buffer, sizeof buffer,
                          "<text x=\"%.1f\" y=\"%.1f\" font-family=\"sans-serif\" font-size=\"12\" %s>",
                          double(a.x), double(a.y), fill.c_str());
            out += buffer;
            out += svgEscape(item.text);
            std::snprintf(buffer, sizeof buffer, "</text>\n");
            break;
        }
        out += buffer;
    }
    out += "</svg>\n";
    return out;
}

bool SvgDebugDraw::write(const std::string& path) const {
    std::ofstream file(path, std::ios::binary);
    if (!file) return false;
    file << svg();
    return bool(file);
}
