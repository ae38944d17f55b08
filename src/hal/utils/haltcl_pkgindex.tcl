# pkgIndex.tcl for package Hal (halcmd's commands in Tcl): lib/tcl/hal -> lib/libhaltcl.so.
package ifneeded Hal 1.0 [list load [file join $dir .. .. libhaltcl.so] Hal]
