#!/bin/bash
# tripodkins through the fake-HAL harness: Bx Cx Cy pins with defaults, poses both ways, changed base, impossible struts.
exec "$EMC2_HOME/objects/unit/comptest" < script
