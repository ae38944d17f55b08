import namedparams
import oword
