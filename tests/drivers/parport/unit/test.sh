#!/bin/bash
# unit: hal_parport's cfg parser (addresses, port numbers, ppdev names, types, errors) and the
# pin <-> register mapping of every mode.
exec "$EMC2_HOME/objects/unit/parport_unit"
