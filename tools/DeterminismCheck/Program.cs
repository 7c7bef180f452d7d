using System;
using System.Globalization;
using System.IO;

namespace MagnusBall.DeterminismCheck
{
    /// <summary>
    /// The cross-runtime determinism check's command line: flies <see cref="DeterminismShots"/> and prints its summary.
    ///   DeterminismCheck [shots] [dump-file]
    /// </summary>
    public static class Program
    {
        public static int Main(string[] args)
        {
            int shots = args.Length > 0 ? int.Parse(args[0], CultureInfo.InvariantCulture) : 100_000;
            using TextWriter dump = args.Length > 1 ? new StreamWriter(args[1]) : TextWriter.Null;
            Console.WriteLine(new DeterminismShots().Run(shots, dump));
            return 0;
        }
    }
}
