import oword


def __init__(self):
    self.calls = 0
    print("__init__: self is interpreter.this:", self is __import__("interpreter").this)


def __delete__(self):
    print("__delete__ after %d O-word calls" % self.calls)
