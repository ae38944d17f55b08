// emc_nml.hh: everything a program needs to talk over emcCommand, emcStatus and emcError.
#ifndef EMC_NML_HH
#define EMC_NML_HH

#include "emc_channel.hh"
#include "emc_cmd_io.hh"
#include "emc_cmd_motion.hh"
#include "emc_cmd_task.hh"
#include "emc_codec.hh"
#include "emc_enums.h"
#include "emc_msg_list.h"
#include "emc_stat.hh"
#include "nml_base.hh"
#include "tooldata.h"

#endif
