#!/bin/bash
# The control points behind NURBS_G5_FEED: G5 (start, start+IJ, end+PQ, end; without I J the first
# handle mirrors the previous second one), G5.1 (start, start+IJ, end), G5.2 blocks with weights P.
"$EMC2_HOME/objects/unit/spline_points_unit"
