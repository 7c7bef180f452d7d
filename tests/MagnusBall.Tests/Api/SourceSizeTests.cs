using System.IO;
using System.Linq;
using MagnusBall.Tests.Contact;
using NUnit.Framework;

namespace MagnusBall.Tests.Api
{
    /// <summary>
    /// Every hand-written source file reads in one sitting (issue 38): at most 600 lines, a large class split by concern into
    /// partial files (docs/architecture.md, "Where the code lives"). The generated Stepanek table is the one exception.
    /// </summary>
    public class SourceSizeTests
    {
        [Test]
        public void NoHandWrittenSourceFile_IsOver600Lines()
        {
            string src = Path.Combine(BounceFigure.RepositoryRoot(), "src");
            var files = Directory.EnumerateFiles(src, "*.cs", SearchOption.AllDirectories)
                .Where(f => !f.Contains(Path.DirectorySeparatorChar + "obj" + Path.DirectorySeparatorChar) && Path.GetFileName(f) != "StepanekTable.cs")
                .ToList();
            var tooLong = files.Select(f => (File: Path.GetRelativePath(src, f), Lines: File.ReadAllLines(f).Length)).Where(f => f.Lines > 600).ToList();
            Assert.That(files.Count, Is.GreaterThan(100));
            Assert.That(tooLong, Is.Empty, "split by concern into partial files");
        }
    }
}
