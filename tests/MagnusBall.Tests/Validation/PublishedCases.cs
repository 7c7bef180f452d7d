using System;
using System.IO;
using System.Text.Json;
using NUnit.Framework;

namespace MagnusBall.Tests.Validation
{
    /// <summary>
    /// Finds and reads the published reference cases in shared/reference/*.json. CI clones the repository
    /// with shared/ beside it (repo/../shared/reference); locally the worktree may sit deeper, so the search
    /// walks up from the test assembly's directory, checking each ancestor and its "shared" child.
    /// </summary>
    internal static class PublishedCases
    {
        public static string Directory()
        {
            string? dir = TestContext.CurrentContext.TestDirectory;
            string start = dir ?? "(unknown)";
            while (dir != null)
            {
                string candidate = Path.Combine(dir, "shared", "reference");
                if (System.IO.Directory.Exists(candidate))
                {
                    return candidate;
                }

                dir = Path.GetDirectoryName(dir);
            }

            Assert.Fail($"No shared/reference folder found above {start}. The validation data lives in <repo>/../shared/reference/*.json (CI clones the repository with shared/ beside it).");
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
