"""Render: RobotModels -> {package path: text}, in memory, through one Jinja environment.

package.py (which source makes which file), environment.py (Jinja settings and what templates
get), static_files.py (robot-independent C++ copied as it is), literals.py (C++/XML/YAML escaping
filters), banner.py (the generated-file header), markers.py (user-region marker syntax). Templates
live in rhi_gen/templates/, the robot-independent C++ in rhi_gen/cpp/, each transport's C++ and glue
template in rhi_gen/transports/<name>/.
"""
