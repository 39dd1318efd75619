"""Typed YAML reading: YAML text -> a tree that remembers every key's line, and typed reads from it.

The layer between the model and everything that validates YAML: the vendor YAML's top-level schema
(inputs/vendor_config.py), robots/package.yaml (inputs/package_info.py) and each transport's
``transport_options`` (transports/<name>/) all read through ``Validator``, so their errors are worded
the same way (file:line: key: problem -> fix). It knows YAML, not robots: it imports only errors.py
and the did-you-mean of model/naming.py.
"""
