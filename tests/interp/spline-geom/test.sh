#!/bin/bash
# G5/G5.1 geometry: biarcs end on the curve, are tangent-continuous and within the tolerance.
"$EMC2_HOME/objects/unit/spline_geom_unit"
