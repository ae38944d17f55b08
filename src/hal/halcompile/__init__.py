"""halcompile package: .comp parser, C generator, man page writer and CLI."""
