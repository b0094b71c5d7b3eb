"""The design specification: a TOML file of sections, validated by pydantic models, and its SI view.

Units are in the key names (``_mm``, ``_deg``, ``_rpm``, ``_MPa``); :func:`si` converts them to SI,
the design never does.  Timing angles are crank degrees, cam segment angles camshaft degrees.
"""

from .cam_base import main_half_angle_deg
from .cams import LAWS, REGISTRY, Cam
from .messages import SpecError
from .engine_sections import resolve_path
from .models import Engine, Spec, Valve, validate
from .reading import example_spec, example_text, input_files, load_spec, parse_spec, spec_toml, toml_tables
from .si import si
from .validate import crank_geometry, set_keys, spec_document

__all__ = ["Cam", "Engine", "LAWS", "REGISTRY", "Spec", "SpecError", "Valve", "crank_geometry", "example_spec",
           "example_text", "input_files", "load_spec", "main_half_angle_deg", "parse_spec", "resolve_path", "set_keys", "si",
           "spec_document", "spec_toml", "toml_tables", "validate"]
