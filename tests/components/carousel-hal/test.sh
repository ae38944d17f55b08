#!/bin/bash
# Load carousel in real HAL: arrays of module parameters, a move already in position, an unknown encoding
# reported and ignored, and too many sense pins failing the load with its message.
halrun -f carousel.hal || echo "halrun failed"
halrun -f bad.hal 2>&1 | grep -E '^carousel'
halrun -f toomany.hal 2>&1 | grep -E '^carousel|insmod'
