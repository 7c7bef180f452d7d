using System;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Bad input: a scenario or aim file that does not follow the format, or bad command-line arguments.
    /// The message names the bad field by its JSON path (for example
    /// <c>scenarios[0].ball.mass: must be finite and &gt; 0; got -1</c>). The CLI exits with code 2.
    /// </summary>
    internal sealed class InputError : Exception
    {
        public InputError(string path, string problem)
            : base(path.Length == 0 ? problem : path + ": " + problem)
        {
            Path = path;
        }

        /// <summary>The JSON path of the bad field ("" for the whole document or the command line).</summary>
        public string Path { get; }
    }
}
