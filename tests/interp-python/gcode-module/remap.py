import emccanon


def m440(self, **words):
    emccanon.MESSAGE("M440 P%g in a preview (task=%d)" % (words["p"], self.task))
    self.execute("G1 X%g F50" % words["p"])
