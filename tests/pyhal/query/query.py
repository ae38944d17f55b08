"""query.py: prints hal.query results for the configuration of setup.hal."""
import hal.query as q

import hal


def show(label, value):
    """Print one labelled result, dict keys sorted, without ids (they depend on load history)."""
    if isinstance(value, dict):
        value = {k: value[k] for k in sorted(value) if k != "comp_id"}
    print("%s -> %s" % (label, value))


show("pin", q.pin("sampler.0.pin.0"))
show("pin by alias", q.pin("smp-enable"))
show("pin by original", q.pin("sampler.0.enable")["alias"])
show("param", q.param("sampler.0.tmax"))
show("signal", q.signal("b"))
comp = q.comp("sampler")
show("comp", {k: comp[k] for k in ("haltype", "name", "type", "pid", "ready", "insmod")})
show("comp by id", q.comp(comp["id"])["name"])
show("funct", q.funct("sampler.0"))
slow = q.thread("slow")
show("thread", slow)
show("missing", (q.pin("nosuch"), q.param("nosuch"), q.signal("nosuch"), q.comp("nosuch"),
                 q.funct("nosuch"), q.thread("nosuch")))
show("pins", sorted(n for n in q.pins() if n.startswith("streamer.0.pin")))
show("signals", sorted(q.signals()))
show("threads", sorted(q.threads()))
show("functs", sorted(q.functs()))
show("params", len([n for n in q.params() if n.startswith("sampler.")]))
show("comps", sorted(n for n in q.comps() if not n.startswith("halcmd")))
show("signalpins", sorted(q.signalpins("f")))
show("signalpins of a missing signal", q.signalpins("nosuch"))
show("types", (hal.query is q, q.pin("sampler.0.pin.1")["type"] is hal.Type.BOOL))
