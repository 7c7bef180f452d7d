using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.Loader;
using System.Threading.Tasks;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using NUnit.Framework;

namespace MagnusBall.Docs.Tests
{
    /// <summary>
    /// Every C# block (```csharp) in the repository's Markdown compiles as C# 9 against the library and netstandard2.1
    /// (as Unity compiles a script) and runs as pasted into a blank console program, as a reader would paste it. A block that goes on from the one before
    /// it says so with <c>&lt;!-- continues --&gt;</c> on the line above its fence: it is run joined to that block. A
    /// A comment <c>// prints: TEXT</c> in a block says what it prints, and the test holds it to that. A
    /// Unity script says so with <c>&lt;!-- engine: unity --&gt;</c>: it is compiled (not run) against the stub of
    /// UnityEngine in tests/UnityStubs and the components built on it, as a script in a Unity project's Assets is.
    /// </summary>
    [TestFixture]
    public sealed class DocBlockTests
    {
        /// <summary>One runnable program: a block, with the blocks it continues.</summary>
        public sealed class DocProgram
        {
            public DocProgram(string name, string source, bool unity = false)
            {
                Name = name;
                Source = source;
                Unity = unity;
            }

            public string Name { get; }

            public string Source { get; }

            /// <summary>A Unity script: compiled against the stub, not run.</summary>
            public bool Unity { get; }

            public override string ToString() => Name;
        }

        private static string Root()
        {
            string? dir = TestContext.CurrentContext.TestDirectory;
            while (dir is not null && !File.Exists(Path.Combine(dir, "MagnusBall.sln")))
            {
                dir = Path.GetDirectoryName(dir);
            }

            return dir ?? throw new InvalidOperationException("MagnusBall.sln not found above the test directory");
        }

        private static IEnumerable<string> MarkdownFiles(string root) =>
            Directory.EnumerateFiles(root, "*.md", SearchOption.AllDirectories)
                .Where(f =>
                {
                    string rel = Path.GetRelativePath(root, f).Replace('\\', '/');
                    return !rel.StartsWith("artifacts/", StringComparison.Ordinal) && !rel.StartsWith(".git/", StringComparison.Ordinal) &&
                           !rel.Contains("/node_modules/", StringComparison.Ordinal) && !rel.Contains("/bin/", StringComparison.Ordinal) &&
                           !rel.Contains("/obj/", StringComparison.Ordinal);
                })
                .OrderBy(f => f, StringComparer.Ordinal);

        /// <summary>Every program of every Markdown file, named "file:line".</summary>
        public static IEnumerable<DocProgram> Programs()
        {
            string root = Root();
            foreach (string file in MarkdownFiles(root))
            {
                string rel = Path.GetRelativePath(root, file).Replace('\\', '/');
                string[] lines = File.ReadAllLines(file);
                string? current = null;
                string? currentName = null;
                for (int i = 0; i < lines.Length; i++)
                {
                    string fence = lines[i].Trim();
                    if (!(fence == "```csharp" || fence == "```cs" || fence == "```c#"))
                    {
                        continue;
                    }

                    int end = i + 1;
                    while (end < lines.Length && lines[end].Trim() != "```")
                    {
                        end++;
                    }

                    string body = string.Join("\n", lines, i + 1, end - i - 1);
                    string marker = PreviousNonEmpty(lines, i);
                    string name = $"{rel}:{i + 1}";
                    if (marker == "<!-- engine: unity -->")
                    {
                        yield return new DocProgram(name, body, unity: true);
                    }
                    else if (marker.StartsWith("<!--", StringComparison.Ordinal) && marker.Contains("engine", StringComparison.Ordinal))
                    {
                        throw new InvalidOperationException($"{name}: unknown engine marker '{marker}'; the one known is '<!-- engine: unity -->'");
                    }
                    else if (marker == "<!-- continues -->")
                    {
                        if (current is null)
                        {
                            throw new InvalidOperationException($"{name}: '<!-- continues -->' but no C# block before it in {rel}");
                        }

                        current = Join(current, body);
                        currentName += "+" + (i + 1);
                    }
                    else
                    {
                        if (current is not null)
                        {
                            yield return new DocProgram(currentName!, current);
                        }

                        current = body;
                        currentName = name;
                    }

                    i = end;
                }

                if (current is not null)
                {
                    yield return new DocProgram(currentName!, current);
                }
            }
        }

        /// <summary>
        /// A block joined to the program before it, as a reader pastes it below: its using directives go to the top
        /// with the others (C# wants them before any statement), its statements after the program's.
        /// </summary>
        private static string Join(string program, string block)
        {
            var usings = new List<string>();
            var statements = new List<string>();
            foreach (string line in (program + "\n" + block).Split('\n'))
            {
                (UsingDirective.IsMatch(line) ? usings : statements).Add(line);
            }

            return string.Join("\n", usings.Distinct(StringComparer.Ordinal).Concat(statements));
        }

        private static readonly System.Text.RegularExpressions.Regex UsingDirective =
            new System.Text.RegularExpressions.Regex(@"^\s*using\s+(static\s+)?[\w.]+(\s*=\s*[\w.<>, ]+)?\s*;\s*$");

        private static string PreviousNonEmpty(string[] lines, int index)
        {
            for (int j = index - 1; j >= 0; j--)
            {
                if (lines[j].Trim().Length > 0)
                {
                    return lines[j].Trim();
                }
            }

            return string.Empty;
        }

        [Test]
        public void TheDocsHaveBlocks() => Assert.That(Programs().Count(), Is.GreaterThanOrEqualTo(5), "the extraction finds README's and the docs' blocks");

        [TestCaseSource(nameof(Programs))]
        public void CompilesAndRunsAsPasted(DocProgram program)
        {
            byte[] image = Compile(program);
            if (program.Unity)
            {
                return; // compiled against the stub: Unity runs it, not this test
            }

            string output = Run(image, program.Name);
            TestContext.Out.WriteLine(output);

            // What a block says it prints ("// prints: ..."), it prints: the docs' numbers are the code's.
            foreach (System.Text.RegularExpressions.Match m in Prints.Matches(program.Source))
            {
                Assert.That(output, Does.Contain(m.Groups[1].Value.Trim()), $"{program.Name} says it prints '{m.Groups[1].Value.Trim()}'");
            }
        }

        private static readonly System.Text.RegularExpressions.Regex Prints =
            new System.Text.RegularExpressions.Regex(@"//\s*prints:\s*(.+)$", System.Text.RegularExpressions.RegexOptions.Multiline);

        private static byte[] Compile(DocProgram program)
        {
            SyntaxTree tree = CSharpSyntaxTree.ParseText(program.Source, new CSharpParseOptions(LanguageVersion.CSharp9), path: program.Name);
            // netstandard2.1's reference assembly and the library: what a Unity project compiles a script against.
            var references = new List<MetadataReference>
            {
                MetadataReference.CreateFromFile(Path.Combine(TestContext.CurrentContext.TestDirectory, "netstandard2.1", "netstandard.dll")),
                MetadataReference.CreateFromFile(typeof(MagnusBall.Ball).Assembly.Location),
            };
            if (program.Unity)
            {
                string bin = TestContext.CurrentContext.TestDirectory;
                references.Add(MetadataReference.CreateFromFile(Path.Combine(bin, "MagnusBall.UnityStubs.dll")));
                references.Add(MetadataReference.CreateFromFile(Path.Combine(bin, "MagnusBall.Unity.dll")));
            }
            CSharpCompilation compilation = CSharpCompilation.Create(
                "DocBlock", new[] { tree }, references,
                new CSharpCompilationOptions(program.Unity ? OutputKind.DynamicallyLinkedLibrary : OutputKind.ConsoleApplication, nullableContextOptions: NullableContextOptions.Disable, allowUnsafe: false));
            using var stream = new MemoryStream();
            Microsoft.CodeAnalysis.Emit.EmitResult result = compilation.Emit(stream);
            string[] errors = result.Diagnostics.Where(d => d.Severity == DiagnosticSeverity.Error).Select(d => d.ToString()).ToArray();
            Assert.That(errors, Is.Empty, $"{program.Name} does not compile as pasted:\n{program.Source}");
            return stream.ToArray();
        }

        private static string Run(byte[] image, string name)
        {
            var context = new AssemblyLoadContext(name, isCollectible: true);
            TextWriter console = Console.Out;
            var captured = new StringWriter();
            try
            {
                Assembly assembly = context.LoadFromStream(new MemoryStream(image));
                MethodInfo entry = assembly.EntryPoint!;
                Console.SetOut(captured);
                Task run = Task.Run(() => entry.Invoke(null, entry.GetParameters().Length == 0 ? null : new object[] { Array.Empty<string>() }));
                Assert.That(run.Wait(TimeSpan.FromSeconds(60)), Is.True, $"{name} ran for more than a minute");
            }
            catch (AggregateException e) when (e.InnerException is TargetInvocationException t)
            {
                Assert.Fail($"{name} throws when run: {t.InnerException}");
            }
            finally
            {
                Console.SetOut(console);
                context.Unload();
            }

            return captured.ToString();
        }
    }
}
