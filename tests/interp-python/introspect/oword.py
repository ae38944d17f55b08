def show(self, *args):
    p = self.params
    print("locals:", p.locals())
    g = p.globals()
    print("globals hold _tau, _x, _ini[setup]depth, _mine, top:",
          all(n in g for n in ("_tau", "_x", "_ini[setup]depth", "_mine", "top")))
    p["inner"] = 5
    ctx = self.sub_context
    print("contexts:", len(ctx), ctx[1].subname, ctx[1].saved_params[0])
    for item in ctx[1].named_params:
        print("  level 1 local", item.key(), item.data().value, item.data().attr)
    top = ctx[0].named_params
    print("attrs: _tau %d, _x %d, _ini %d, _mine %d, top %d" % (
        top["_tau"].attr, top["_x"].attr, top["_ini[setup]depth"].attr, top["_mine"].attr, top["top"].attr))
    print("_tau via params:", p["_tau"], "#5400:", p[5400], "tool 0:", self.tool_table[0].toolno,
          "offset z:", self.tool_table[0].offset.z)
    print("active g codes:", self.active_g_codes[1:8], "motion mode", self.motion_mode)
    print("blocks[0] is the call:", self.blocks[0].o_name, self.blocks[0].params[:3])
    self.tool_table[0].diameter = 0.25
    return len(args)
