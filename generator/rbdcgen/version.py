"""The generator's version, written into every banner (changing it changes every generated file)."""
VERSION = "0.1.0"
