#!/bin/bash
# Load carousel in real HAL: arrays of module parameters, a move already in position, and a
# bad encoding that fails the load with its message.
halrun -f carousel.hal || echo "halrun failed"
halrun -f bad.hal 2>&1 | grep '^carousel:'
