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
            try
            {
                return JsonDocument.Parse(text, DocumentOptions);
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
                            frames[^1] = (isArray, index, reader.GetString());
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
