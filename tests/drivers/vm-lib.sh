# vm-lib.sh: sourced by the driver tests that need kernel features this machine lacks (vcan,
# gpio-sim, a parallel port): where the VM is and how to run a script inside it.
# OPENEMC_VM_DIR overrides the default place, ../shared/vm seen from the repository.
VM_DIR=${OPENEMC_VM_DIR:-$(dirname "$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)")/shared/vm}
# vm-run keeps its kernels and modules here unless VM_WORK says otherwise (same default as vm-run).
[ -d "$VM_DIR" ] && export VM_WORK=${VM_WORK:-$(cd "$VM_DIR/../../.." && pwd)/vmwork}

# vm_unusable: prints why the VM cannot be used and succeeds, or fails when it can be used.
vm_unusable() {
    if [ ! -x "$VM_DIR/vm-run" ]; then
        echo "needs the VM ($VM_DIR/vm-run not found)"
        return 0
    fi
    if [ "$(id -u)" != 0 ] && ! command -v qemu-system-x86_64 > /dev/null; then
        echo "needs the VM (qemu-system-x86_64 missing and not root to install it)"
        return 0
    fi
    return 1
}

# vm_run [vm-run options] -- COMMAND...: runs COMMAND in the VM (the repository shared read-write).
vm_run() {
    VM_TIMEOUT=${VM_TIMEOUT:-300} "$VM_DIR/vm-run" "$@"
}

# vm_modprobe MODULE...: (inside the VM) loads kernel modules the VM's initramfs does not carry
# from the unpacked kernel package vm-run boots.
vm_modprobe() {
    local root=$VM_WORK/$(uname -r)/modroot m
    for m in "$@"; do
        modprobe -d "$root" "$m" || { echo "cannot load kernel module $m from $root"; return 1; }
    done
}
