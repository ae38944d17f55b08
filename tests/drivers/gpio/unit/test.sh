#!/bin/bash
# unit: hal_gpio's argument checks: specs and flags per line, ignored options of inputs, unknown,
# duplicate, empty and over-long names, contradicting electrical options.
exec "$EMC2_HOME/objects/unit/gpio_args_unit"
