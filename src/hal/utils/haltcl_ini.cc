// haltcl_ini.cc: `hal --ini-entries FILE`: every SECTION, KEY, value of an INI file for haltcl's arrays.
#include <tcl.h>

#include <string>

#include "emc/ini/inifile.hh"

extern "C" int haltcl_ini_entries(Tcl_Interp *interp, const char *path);

// Set the result to a flat list {section key value ...} in file order; an error if unparsable.
int haltcl_ini_entries(Tcl_Interp *interp, const char *path)
{
    IniFile ini;
    if (!ini.Open(path)) {
        std::string why = ini.ErrorText().empty() ? "invalid INI file" : ini.ErrorText();
        Tcl_SetObjResult(interp, Tcl_ObjPrintf("%s: %s", path, why.c_str()));
        return TCL_ERROR;
    }
    Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
    for (const IniSection &section : ini.AllSections()) {
        for (const IniEntry &entry : section.entries) {
            Tcl_ListObjAppendElement(interp, list, Tcl_NewStringObj(section.name.c_str(), -1));
            Tcl_ListObjAppendElement(interp, list, Tcl_NewStringObj(entry.key.c_str(), -1));
            Tcl_ListObjAppendElement(interp, list,
                                     Tcl_NewStringObj(entry.value.data(), int(entry.value.size())));
        }
    }
    Tcl_SetObjResult(interp, list);
    return TCL_OK;
}
