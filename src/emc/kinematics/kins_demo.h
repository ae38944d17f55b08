/* kins_demo.h: the demonstration items LinuxCNC's userkins template gives its copies (millturn): an fpin
 * pin and fdemo funct per instance, and in/out pins echoed by every inverse call. */
#ifndef KINS_DEMO_H
#define KINS_DEMO_H

/* Instance items <prefix>.fpin (s32 OUT) and funct <prefix>.fdemo; 0 or -errno. */
int kins_demo_instance(int comp_id, int i, const char *prefix);
/* Pins <module>.in (u32 IN) and <module>.out (u32 OUT); 0 or -errno. */
int kins_demo_echo_pins(int comp_id, const char *module);
/* Inverse side: copy in to out. */
void kins_demo_echo_inverse(void);
/* Forward side: say once that in is not echoed while no inverse has run. */
void kins_demo_echo_forward(const char *module);

#endif
