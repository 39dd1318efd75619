"""Render: RobotModels -> {package path: text}, in memory, through one Jinja environment.

package.py (which templates make which files), environment.py (Jinja settings and what templates
get), literals.py (C++/XML/YAML escaping filters), banner.py (the generated-file header),
markers.py (user-region marker syntax). Templates live in rhi_gen/templates/.
"""
