using System.IO;
using System.Linq;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Writes the CLI's JSON: built with a <see cref="Utf8JsonWriter"/> (shortest round-trip numbers, proper
    /// escaping), then laid out for people: two-space indentation, with arrays of numbers (vectors) kept on
    /// one line.
    /// </summary>
    internal static class JsonOutput
    {
        private static readonly JsonWriterOptions Compact = new JsonWriterOptions
        {
            Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        };

        private static readonly JsonSerializerOptions NameOptions = new JsonSerializerOptions
        {
            Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
        };

        /// <summary>Runs <paramref name="write"/> on a fresh writer and returns the laid-out text, ending in a newline.</summary>
        public static string Write(System.Action<Utf8JsonWriter> write)
        {
            using var buffer = new MemoryStream();
            using (var writer = new Utf8JsonWriter(buffer, Compact))
            {
                write(writer);
            }

            using JsonDocument document = JsonDocument.Parse(buffer.ToArray());
            var text = new StringBuilder();
            Layout(document.RootElement, text, 0);
            return text.Append('\n').ToString();
        }

        private static void Layout(JsonElement e, StringBuilder text, int depth)
        {
            switch (e.ValueKind)
            {
                case JsonValueKind.Object:
                    if (!e.EnumerateObject().Any())
                    {
                        text.Append("{}");
                        return;
                    }

                    text.Append("{\n");
                    bool firstProperty = true;
                    foreach (JsonProperty p in e.EnumerateObject())
                    {
                        if (!firstProperty)
                        {
                            text.Append(",\n");
                        }

                        firstProperty = false;
                        text.Append(' ', 2 * (depth + 1));
                        text.Append(JsonSerializer.Serialize(p.Name, NameOptions));
                        text.Append(": ");
                        Layout(p.Value, text, depth + 1);
                    }

                    text.Append('\n').Append(' ', 2 * depth).Append('}');
                    return;

                case JsonValueKind.Array:
                    if (e.GetArrayLength() == 0)
                    {
                        text.Append("[]");
                        return;
                    }

                    if (e.EnumerateArray().All(x => x.ValueKind == JsonValueKind.Number))
                    {
                        text.Append('[').Append(string.Join(", ", e.EnumerateArray().Select(x => x.GetRawText()))).Append(']');
                        return;
                    }

                    text.Append("[\n");
                    bool firstItem = true;
                    foreach (JsonElement item in e.EnumerateArray())
                    {
                        if (!firstItem)
                        {
                            text.Append(",\n");
                        }

                        firstItem = false;
                        text.Append(' ', 2 * (depth + 1));
                        Layout(item, text, depth + 1);
                    }

                    text.Append('\n').Append(' ', 2 * depth).Append(']');
                    return;

                default:
                    text.Append(e.GetRawText());
                    return;
            }
        }
    }
}
