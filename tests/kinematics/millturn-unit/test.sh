#!/bin/bash
# millturn turning map: known poses, round trips, handedness.
exec "$EMC2_HOME/objects/unit/millturn_unit"
