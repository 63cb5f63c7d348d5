"""A JSON Schema validator for the subset docs/ir.schema.json uses (no third-party package needed):
type, const, enum, properties, required, additionalProperties: false, items, minItems, maxItems,
minimum and local "$ref": "#/$defs/…". A schema using any other keyword is refused rather than
half-checked, so the schema cannot silently outgrow this validator."""

_TYPES = {
    "object": lambda x: isinstance(x, dict),
    "array": lambda x: isinstance(x, list),
    "string": lambda x: isinstance(x, str),
    "boolean": lambda x: isinstance(x, bool),
    "null": lambda x: x is None,
    "integer": lambda x: isinstance(x, int) and not isinstance(x, bool),
    "number": lambda x: isinstance(x, (int, float)) and not isinstance(x, bool),
}
_ANNOTATIONS = {"$schema", "$id", "$defs", "title", "description"}
_KEYWORDS = {"type", "const", "enum", "properties", "required", "additionalProperties", "items",
             "minItems", "maxItems", "minimum", "$ref"}


class SchemaError(ValueError):
    """The schema uses a keyword this validator does not implement."""


def errors(instance, schema, root=None, where="$"):
    """The list of violations of `schema` by `instance`, each naming the element ("$.joints[2].type")."""
    root = schema if root is None else root
    unknown = set(schema) - _KEYWORDS - _ANNOTATIONS
    if unknown:
        raise SchemaError("%s: unsupported keywords %s" % (where, sorted(unknown)))
    if not isinstance(schema.get("additionalProperties", False), bool):
        raise SchemaError("%s: additionalProperties must be true or false here" % where)
    if "$ref" in schema:
        prefix = "#/$defs/"
        if not schema["$ref"].startswith(prefix):
            raise SchemaError("%s: only local #/$defs/ references are supported" % where)
        return errors(instance, root["$defs"][schema["$ref"][len(prefix):]], root, where)
    found = []
    if "type" in schema:
        types = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        if not any(_TYPES[t](instance) for t in types):
            return ["%s: expected %s, got %r" % (where, " or ".join(types), instance)]
    if "const" in schema and instance != schema["const"]:
        found.append("%s: expected %r, got %r" % (where, schema["const"], instance))
    if "enum" in schema and instance not in schema["enum"]:
        found.append("%s: expected one of %r, got %r" % (where, schema["enum"], instance))
    if "minimum" in schema and _TYPES["number"](instance) and instance < schema["minimum"]:
        found.append("%s: %r is below the minimum %r" % (where, instance, schema["minimum"]))
    if isinstance(instance, dict):
        for key in schema.get("required", []):
            if key not in instance:
                found.append("%s: missing key '%s'" % (where, key))
        properties = schema.get("properties", {})
        for key, value in instance.items():
            if key in properties:
                found += errors(value, properties[key], root, "%s.%s" % (where, key))
            elif schema.get("additionalProperties", True) is False:
                found.append("%s: unexpected key '%s'" % (where, key))
    if isinstance(instance, list):
        if len(instance) < schema.get("minItems", 0):
            found.append("%s: fewer than %d items" % (where, schema["minItems"]))
        if len(instance) > schema.get("maxItems", len(instance)):
            found.append("%s: more than %d items" % (where, schema["maxItems"]))
        if "items" in schema:
            for k, item in enumerate(instance):
                found += errors(item, schema["items"], root, "%s[%d]" % (where, k))
    return found
