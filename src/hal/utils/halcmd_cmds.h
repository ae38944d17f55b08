/* halcmd_cmds.h: handler prototypes of every halcmd command. */
#ifndef HALCMD_CMDS_H
#define HALCMD_CMDS_H

#define HC_HANDLER(name) int hc_cmd_##name(int argc, char *argv[])

HC_HANDLER(loadrt); HC_HANDLER(loadusr); HC_HANDLER(waitusr);
HC_HANDLER(unloadrt); HC_HANDLER(unloadusr); HC_HANDLER(unload);
HC_HANDLER(net); HC_HANDLER(linkps); HC_HANDLER(linksp); HC_HANDLER(linkpp);
HC_HANDLER(unlinkp); HC_HANDLER(newsig); HC_HANDLER(delsig);
HC_HANDLER(setp); HC_HANDLER(sets); HC_HANDLER(getp); HC_HANDLER(gets);
HC_HANDLER(ptype); HC_HANDLER(stype);
HC_HANDLER(addf); HC_HANDLER(initf); HC_HANDLER(delf);
HC_HANDLER(start); HC_HANDLER(stop);
HC_HANDLER(show); HC_HANDLER(list); HC_HANDLER(save); HC_HANDLER(status);
HC_HANDLER(lock); HC_HANDLER(unlock); HC_HANDLER(alias); HC_HANDLER(unalias);
HC_HANDLER(source); HC_HANDLER(echo); HC_HANDLER(unecho); HC_HANDLER(print);
HC_HANDLER(debug); HC_HANDLER(setexact);

#endif
