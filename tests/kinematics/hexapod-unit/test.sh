#!/bin/bash
# Hexapod math: known strut lengths, round trips, twist correction, refused poses.
exec "$EMC2_HOME/objects/unit/genhex_unit"
