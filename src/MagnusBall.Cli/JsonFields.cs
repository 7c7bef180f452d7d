using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text.Json;

namespace MagnusBall.Cli
{
    /// <summary>
    /// One JSON object being read field by field. It remembers which fields were asked for, so that
    /// <see cref="RejectUnknown"/> can refuse every other field (a typo such as "radus" must not pass
    /// silently) and duplicated fields. Every error names the field by its JSON path.
    /// </summary>
    internal sealed class JsonFields
    {
        private readonly JsonElement _element;
        private readonly HashSet<string> _known = new HashSet<string>(StringComparer.Ordinal);

        private JsonFields(JsonElement element, string path)
        {
            _element = element;
            Path = path;
        }

        /// <summary>The JSON path of this object ("" for the document root).</summary>
        public string Path { get; }

        /// <summary>Reads <paramref name="element"/> as an object, or fails naming <paramref name="path"/>.</summary>
        public static JsonFields Of(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.Object)
            {
                throw new InputError(path, $"must be an object; got {Describe(element)}");
            }

            return new JsonFields(element, path);
        }

        /// <summary>The path of field <paramref name="name"/> of this object.</summary>
        public string PathOf(string name) => Path.Length == 0 ? name : Path + "." + name;

        /// <summary>
        /// The field, or null when it is absent. A JSON null is an error: the format gives null a meaning only for
        /// "ground" (read that with <see cref="IsNull"/>); a default is asked for by leaving the field out.
        /// </summary>
        public JsonElement? Optional(string name)
        {
            _known.Add(name);
            if (!_element.TryGetProperty(name, out JsonElement value))
            {
                return null;
            }

            if (value.ValueKind == JsonValueKind.Null)
            {
                throw new InputError(PathOf(name), "must not be null (leave the field out to get its default)");
            }

            return value;
        }

        /// <summary>Whether the field is present at all (even as null).</summary>
        public bool Has(string name)
        {
            _known.Add(name);
            return _element.TryGetProperty(name, out _);
        }

        /// <summary>Whether the field is present and a JSON null (the one place the format gives null a meaning: "ground").</summary>
        public bool IsNull(string name)
        {
            _known.Add(name);
            return _element.TryGetProperty(name, out JsonElement value) && value.ValueKind == JsonValueKind.Null;
        }

        /// <summary>The field; fails when it is absent or null.</summary>
        public JsonElement Required(string name) =>
            Optional(name) ?? throw new InputError(PathOf(name), "required field is missing");

        /// <summary>A required object field.</summary>
        public JsonFields Object(string name) => Of(Required(name), PathOf(name));

        /// <summary>An optional object field, or null.</summary>
        public JsonFields? OptionalObject(string name)
        {
            JsonElement? value = Optional(name);
            return value.HasValue ? Of(value.Value, PathOf(name)) : null;
        }

        /// <summary>A required string field.</summary>
        public string String(string name) => ReadString(Required(name), PathOf(name));

        /// <summary>An optional string field, or <paramref name="fallback"/>.</summary>
        public string String(string name, string fallback)
        {
            JsonElement? value = Optional(name);
            return value.HasValue ? ReadString(value.Value, PathOf(name)) : fallback;
        }

        /// <summary>A required finite number.</summary>
        public double Number(string name) => ReadNumber(Required(name), PathOf(name));

        /// <summary>An optional finite number, or <paramref name="fallback"/>.</summary>
        public double Number(string name, double fallback)
        {
            JsonElement? value = Optional(name);
            return value.HasValue ? ReadNumber(value.Value, PathOf(name)) : fallback;
        }

        /// <summary>A required number that must be finite and &gt; 0.</summary>
        public double Positive(string name) => CheckPositive(Number(name), PathOf(name));

        /// <summary>An optional number that must be finite and &gt; 0, or <paramref name="fallback"/>.</summary>
        public double Positive(string name, double fallback) => CheckPositive(Number(name, fallback), PathOf(name));

        /// <summary>An optional number that must be finite and &gt;= 0, or <paramref name="fallback"/>.</summary>
        public double NonNegative(string name, double fallback)
        {
            double value = Number(name, fallback);
            if (value < 0)
            {
                throw new InputError(PathOf(name), "must be finite and >= 0; got " + Format(value));
            }

            return value;
        }

        /// <summary>A required number that must be finite and &gt;= 0.</summary>
        public double NonNegativeRequired(string name)
        {
            double value = Number(name);
            if (value < 0)
            {
                throw new InputError(PathOf(name), "must be finite and >= 0; got " + Format(value));
            }

            return value;
        }

        /// <summary>A required vector: an array of exactly three finite numbers.</summary>
        public Vector3d Vector(string name) => ReadVector(Required(name), PathOf(name));

        /// <summary>An optional vector, or <paramref name="fallback"/>.</summary>
        public Vector3d Vector(string name, Vector3d fallback)
        {
            JsonElement? value = Optional(name);
            return value.HasValue ? ReadVector(value.Value, PathOf(name)) : fallback;
        }

        /// <summary>A required vector that must not be zero (a direction).</summary>
        public Vector3d Direction(string name) => CheckNonZero(Vector(name), PathOf(name));

        /// <summary>
        /// Fails on any field that was not asked for, and on any field given twice. Call it after reading
        /// every field the object may have.
        /// </summary>
        public void RejectUnknown()
        {
            var seen = new HashSet<string>(StringComparer.Ordinal);
            foreach (JsonProperty property in _element.EnumerateObject())
            {
                if (!seen.Add(property.Name))
                {
                    throw new InputError(PathOf(property.Name), "field is given more than once");
                }

                if (!_known.Contains(property.Name))
                {
                    string expected = string.Join(", ", _known.OrderBy(n => n, StringComparer.Ordinal));
                    throw new InputError(PathOf(property.Name), $"unknown field; expected one of: {expected}");
                }
            }
        }

        public static string ReadString(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.String)
            {
                throw new InputError(path, $"must be a string; got {Describe(element)}");
            }

            return element.GetString()!;
        }

        public static double ReadNumber(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.Number)
            {
                throw new InputError(path, $"must be a finite number; got {Describe(element)}");
            }

            // A literal such as 1e999 is valid JSON but overflows a double: refuse it rather than fly with infinity.
            if (!element.TryGetDouble(out double value) || !double.IsFinite(value))
            {
                throw new InputError(path, $"must be a finite number; got {element.GetRawText()}");
            }

            return value;
        }

        public static Vector3d ReadVector(JsonElement element, string path)
        {
            if (element.ValueKind != JsonValueKind.Array)
            {
                throw new InputError(path, $"must be an array of 3 finite numbers [x, y, z]; got {Describe(element)}");
            }

            int length = element.GetArrayLength();
            if (length != 3)
            {
                throw new InputError(path, $"must be an array of 3 finite numbers [x, y, z]; got {length} element{(length == 1 ? "" : "s")}");
            }

            return new Vector3d(
                ReadNumber(element[0], path + "[0]"),
                ReadNumber(element[1], path + "[1]"),
                ReadNumber(element[2], path + "[2]"));
        }

        public static double CheckPositive(double value, string path)
        {
            if (!(value > 0))
            {
                throw new InputError(path, "must be finite and > 0; got " + Format(value));
            }

            return value;
        }

        public static Vector3d CheckNonZero(Vector3d value, string path)
        {
            // NormalizedOrZero scales before squaring, so 1e308 and 1e-300 are directions too; only (0, 0, 0) is not.
            if (value.NormalizedOrZero().LengthSquared == 0)
            {
                throw new InputError(path, "must be a non-zero direction; got " + Format(value));
            }

            return value;
        }

        public static string Format(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        public static string Format(Vector3d value) => $"[{Format(value.X)}, {Format(value.Y)}, {Format(value.Z)}]";

        public static string Describe(JsonElement element)
        {
            string text = element.GetRawText();
            if (text.Length > 40)
            {
                text = text.Substring(0, 37) + "...";
            }

            return element.ValueKind switch
            {
                JsonValueKind.Object => "an object",
                JsonValueKind.Array => "an array",
                JsonValueKind.String => "the string " + text,
                JsonValueKind.Null => "null",
                _ => text,
            };
        }
    }
}
