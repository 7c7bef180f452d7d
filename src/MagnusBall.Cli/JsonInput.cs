using System;
using System.Collections.Generic;
using System.Text;
using System.Text.Json;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Parses a JSON document as the CLI accepts it: standard JSON plus // and /* */ comments and trailing
    /// commas (so the annotated example of the format parses as written). Syntax errors are reported with
    /// the JSON path where they occur, the line and the column.
    /// </summary>
    internal static class JsonInput
    {
        private static readonly JsonDocumentOptions DocumentOptions = new JsonDocumentOptions
        {
            CommentHandling = JsonCommentHandling.Skip,
            AllowTrailingCommas = true,
            MaxDepth = 64,
        };

        public static JsonDocument Parse(string text)
        {
            JsonDocument document;
            try
            {
                document = JsonDocument.Parse(text, DocumentOptions);
            }
            catch (ArgumentException e)
            {
                // The text itself is not valid UTF-16 (a lone surrogate character): it cannot be transcoded.
                throw new InputError(string.Empty, "invalid text: " + e.Message.Split('\n')[0].TrimEnd('.') + " (the input must be valid Unicode)");
            }
            catch (JsonException e)
            {
                string where = e.LineNumber.HasValue
                    ? $" (line {e.LineNumber + 1}, column {e.BytePositionInLine + 1})"
                    : string.Empty;
                string path = PathAtError(text);
                string detail = e.Message;
                int cut = detail.IndexOf(" LineNumber:", StringComparison.Ordinal);
                if (cut > 0)
                {
                    detail = detail.Substring(0, cut);
                }

                // JSON has no NaN or Infinity: say so plainly when that is what broke the parse.
                if (detail.Contains("'N'", StringComparison.Ordinal) || detail.Contains("'I'", StringComparison.Ordinal) ||
                    detail.Contains("'-'", StringComparison.Ordinal))
                {
                    detail += " (JSON has no NaN or Infinity: every number must be finite)";
                }

                throw new InputError(path, "invalid JSON" + where + ": " + detail.TrimEnd('.'));
            }

            try
            {
                CheckStrings(document.RootElement, string.Empty);
            }
            catch
            {
                document.Dispose();
                throw;
            }

            return document;
        }

        /// <summary>
        /// Fails on any string or field name holding an escaped lone UTF-16 surrogate ("\ud800"): valid JSON syntax,
        /// but not a character, and unreadable as text. The walk is bounded by the document (depth at most 64).
        /// </summary>
        private static void CheckStrings(JsonElement element, string path)
        {
            switch (element.ValueKind)
            {
                case JsonValueKind.Object:
                    foreach (JsonProperty property in element.EnumerateObject())
                    {
                        string name;
                        try
                        {
                            name = property.Name;
                        }
                        catch (InvalidOperationException)
                        {
                            throw new InputError(path, "a field name holds a lone UTF-16 surrogate escape (such as \\ud800), which is not a character");
                        }

                        CheckStrings(property.Value, path.Length == 0 ? name : path + "." + name);
                    }

                    break;
                case JsonValueKind.Array:
                    int index = 0;
                    foreach (JsonElement item in element.EnumerateArray())
                    {
                        CheckStrings(item, $"{path}[{index}]");
                        index++;
                    }

                    break;
                case JsonValueKind.String:
                    try
                    {
                        element.GetString();
                    }
                    catch (InvalidOperationException)
                    {
                        throw new InputError(path, "the string holds a lone UTF-16 surrogate escape (such as \\ud800), which is not a character");
                    }

                    break;
            }
        }

        /// <summary>The JSON path of the value being read when the reader fails ("" if it fails at the root).</summary>
        private static string PathAtError(string text)
        {
            var frames = new List<(bool IsArray, int Index, string? Property)>();
            var reader = new Utf8JsonReader(Encoding.UTF8.GetBytes(text), new JsonReaderOptions
            {
                CommentHandling = JsonCommentHandling.Skip,
                AllowTrailingCommas = true,
                MaxDepth = 64,
            });
            try
            {
                while (reader.Read())
                {
                    switch (reader.TokenType)
                    {
                        case JsonTokenType.StartObject:
                        case JsonTokenType.StartArray:
                            BeginValue(frames);
                            frames.Add((reader.TokenType == JsonTokenType.StartArray, -1, null));
                            break;
                        case JsonTokenType.EndObject:
                        case JsonTokenType.EndArray:
                            frames.RemoveAt(frames.Count - 1);
                            break;
                        case JsonTokenType.PropertyName:
                            (bool isArray, int index, _) = frames[^1];
                            string? name;
                            try
                            {
                                name = reader.GetString();
                            }
                            catch (InvalidOperationException)
                            {
                                name = "?"; // a lone surrogate in the name: reported when the document parses
                            }

                            frames[^1] = (isArray, index, name);
                            break;
                        default:
                            BeginValue(frames);
                            break;
                    }
                }
            }
            catch (JsonException)
            {
                // Inside an array, the failing token is the element after the last one read.
                if (frames.Count > 0 && frames[^1].IsArray)
                {
                    (bool isArray, int index, string? property) = frames[^1];
                    frames[^1] = (isArray, index + 1, property);
                }
            }

            var path = new StringBuilder();
            foreach ((bool isArray, int index, string? property) in frames)
            {
                if (isArray)
                {
                    path.Append('[').Append(Math.Max(index, 0)).Append(']');
                }
                else if (property != null)
                {
                    if (path.Length > 0)
                    {
                        path.Append('.');
                    }

                    path.Append(property);
                }
            }

            return path.ToString();
        }

        private static void BeginValue(List<(bool IsArray, int Index, string? Property)> frames)
        {
            if (frames.Count > 0 && frames[^1].IsArray)
            {
                (bool isArray, int index, string? property) = frames[^1];
                frames[^1] = (isArray, index + 1, property);
            }
        }
    }
}
