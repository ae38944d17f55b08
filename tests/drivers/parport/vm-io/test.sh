#!/bin/bash
# vm-io: hal_parport on two emulated parallel ports inside the VM: pin, param and funct names,
# output bytes in the data and control registers, inputs, modes out/in/x, ppdev and raw access,
# strobed bytes arriving at the emulated printer, reset pulses and the reset-time clamp.
. "$EMC2_HOME/tests/drivers/vm-lib.sh"
printer0=$(mktemp)
printer1=$(mktemp)
trap 'rm -f "$printer0" "$printer1"' EXIT
export VM_QEMU_ARGS="-chardev file,id=pp0,path=$printer0 -device isa-parallel,chardev=pp0,iobase=0x378,irq=7
 -chardev file,id=pp1,path=$printer1 -device isa-parallel,chardev=pp1,iobase=0x278,irq=5"
vm_run -- bash ./inner.sh
echo "vm status $?"
# 'O' and 'K' were strobed once each; '!' once per cycle while the reset function ran
bytes=$(cat "$printer0" "$printer1")
echo "printer: ${bytes:0:2}, then ${bytes:2:1} more than once: $( [[ ${bytes:2} =~ ^!!+$ ]] && echo yes || echo "no (${bytes:2})")"
