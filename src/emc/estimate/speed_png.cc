// speed_png.cc: the toolpath seen from above (XY), each servo step coloured by its speed, written as a PNG (libpng).
#include "speed_png.hh"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace {

const int SIZE = 900;           // picture width and height, pixels
const int MARGIN = 30;
const int BAR = 14;             // height of the colour bar at the bottom
struct Rgb {
    unsigned char r, g, b;
};
const Rgb BACKGROUND = {255, 255, 255}, TRAVERSE = {190, 190, 190};

// Blue (rest) through cyan, green, yellow to red (the top speed).
Rgb speed_colour(double f)
{
    static const Rgb stops[] = {{0, 0, 200}, {0, 190, 230}, {0, 190, 0}, {240, 210, 0}, {220, 0, 0}};
    f = std::fmin(1.0, std::fmax(0.0, f)) * 4.0;
    int k = std::min(3, (int)f);
    double t = f - k;
    const Rgb &a = stops[k], &b = stops[k + 1];
    return {(unsigned char)(a.r + t * (b.r - a.r)), (unsigned char)(a.g + t * (b.g - a.g)),
            (unsigned char)(a.b + t * (b.b - a.b))};
}

class Canvas {
public:
    Canvas() : px_((size_t)SIZE * SIZE, BACKGROUND) {}
    void dot(int x, int y, Rgb c)
    {
        if (x >= 0 && x < SIZE && y >= 0 && y < SIZE) px_[(size_t)y * SIZE + x] = c;
    }
    // Straight line (DDA, one dot per pixel step).
    void line(double x0, double y0, double x1, double y1, Rgb c)
    {
        int n = (int)std::ceil(std::fmax(std::fabs(x1 - x0), std::fabs(y1 - y0)));
        for (int k = 0; k <= n; k++) {
            double t = n ? (double)k / n : 0.0;
            int x = (int)std::lround(x0 + t * (x1 - x0)), y = (int)std::lround(y0 + t * (y1 - y0));
            dot(x, y, c), dot(x + 1, y, c), dot(x, y + 1, c), dot(x + 1, y + 1, c);
        }
    }
    const Rgb *row(int y) const { return &px_[(size_t)y * SIZE]; }

private:
    std::vector<Rgb> px_;
};

// Draw the path scaled into the square, y up; the colour bar along the bottom.
void draw(Canvas &cv, const std::vector<PathPoint> &path, double vmax)
{
    float xmin = 1e30f, xmax = -1e30f, ymin = 1e30f, ymax = -1e30f;
    for (const PathPoint &p : path) {
        xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
    double span = std::fmax(1e-9, std::fmax(xmax - xmin, ymax - ymin));
    double scale = (SIZE - 2 * MARGIN - 2 * BAR) / span;
    auto px = [&](float x) { return MARGIN + (x - xmin) * scale; };
    auto py = [&](float y) { return SIZE - MARGIN - 2 * BAR - (y - ymin) * scale; };
    for (size_t k = 1; k < path.size(); k++) {
        const PathPoint &a = path[k - 1], &b = path[k];
        Rgb c = b.traverse ? TRAVERSE : speed_colour(vmax > 0 ? b.vel / vmax : 0.0);
        cv.line(px(a.x), py(a.y), px(b.x), py(b.y), c);
    }
    for (int x = MARGIN; x < SIZE - MARGIN; x++)
        for (int y = SIZE - MARGIN - BAR; y < SIZE - MARGIN; y++)
            cv.dot(x, y, speed_colour((double)(x - MARGIN) / (SIZE - 2 * MARGIN - 1)));
}

// Write the canvas to path through a temporary file and a rename.
bool write_png(const Canvas &cv, const std::string &path, std::string *error)
{
    std::string tmp = path + ".tmp" + std::to_string(getpid());
    FILE *f = fopen(tmp.c_str(), "wb");
    if (!f) {
        *error = path + ": " + strerror(errno);
        return false;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    bool ok = png && info && !setjmp(png_jmpbuf(png));
    if (ok) {
        png_init_io(png, f);
        png_set_IHDR(png, info, SIZE, SIZE, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png, info);
        for (int y = 0; y < SIZE; y++) png_write_row(png, (png_const_bytep)cv.row(y));
        png_write_end(png, nullptr);
    }
    png_destroy_write_struct(&png, &info);
    ok = (fclose(f) == 0) && ok;
    if (ok && rename(tmp.c_str(), path.c_str()) == 0) return true;
    *error = path + ": can't write the picture" + (errno ? std::string(": ") + strerror(errno) : "");
    unlink(tmp.c_str());
    return false;
}

}  // namespace

bool write_speed_png(const std::string &path, const std::vector<PathPoint> &points, std::string *error)
{
    double vmax = 0.0;
    for (const PathPoint &p : points)
        if (!p.traverse) vmax = std::fmax(vmax, p.vel);
    Canvas cv;
    draw(cv, points, vmax);
    return write_png(cv, path, error);
}
