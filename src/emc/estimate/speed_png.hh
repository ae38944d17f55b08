// speed_png.hh: openemc-estimate --png: the toolpath from above, coloured by speed.
#ifndef SPEED_PNG_HH
#define SPEED_PNG_HH

#include <string>
#include <vector>

#include "estimate_report.hh"

// Draw points (XY, speed) into a PNG at path (temp file + rename); blue = rest, red = the
// fastest feed speed, grey = traverses; a colour bar along the bottom.  false with *error.
bool write_speed_png(const std::string &path, const std::vector<PathPoint> &points, std::string *error);

#endif
