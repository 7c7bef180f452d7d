using System;
using System.IO;
using System.Text.Json;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Finds and reads the published reference cases in the repository's data/published/*.json (see
    /// data/README.md for each file's source). The folder is found by walking up from the test assembly's
    /// directory to the repository root, the folder that holds MagnusBall.sln.
    /// </summary>
    internal static class PublishedCases
    {
        public static string Directory()
        {
            string? dir = TestContext.CurrentContext.TestDirectory;
            string start = dir ?? "(unknown)";
            while (dir != null)
            {
                if (File.Exists(Path.Combine(dir, "MagnusBall.sln")))
                {
                    string candidate = Path.Combine(dir, "data", "published");
                    if (!System.IO.Directory.Exists(candidate))
                    {
                        Assert.Fail($"The repository at {dir} has no data/published folder: the validation data is part of the repository.");
                    }

                    return candidate;
                }

                dir = Path.GetDirectoryName(dir);
            }

            Assert.Fail($"No MagnusBall.sln found above {start}: the tests run from a build of the repository.");
            return string.Empty;
        }

        public static JsonElement Load(string fileName)
        {
            string path = Path.Combine(Directory(), fileName);
            if (!File.Exists(path))
            {
                Assert.Fail($"Reference file {path} is missing.");
            }

            using JsonDocument document = JsonDocument.Parse(File.ReadAllText(path));
            return document.RootElement.Clone();
        }

        public static double Number(this JsonElement element, params string[] path)
        {
            JsonElement e = element;
            foreach (string key in path)
            {
                if (!e.TryGetProperty(key, out e))
                {
                    Assert.Fail($"Reference data has no field {string.Join(".", path)}.");
                }
            }

            return e.GetDouble();
        }

        public static double Radians(double degrees) => degrees * Math.PI / 180;
    }
}
