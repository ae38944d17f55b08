// lcnc_preview.hh: the GEOMETRY transform shared by vertex9 and the position logger.
#ifndef LCNC_PREVIEW_HH
#define LCNC_PREVIEW_HH

#include "lcnc_py.hh"

// Map a 9-axis point (x y z a b c u v w) to a 3-D preview point by a GEOMETRY string.
void lcnc_vertex9(const double pt9[9], double out[3], const char *geometry);

#endif
