namespace MagnusBall.Cli
{
    /// <summary>The `aim` command: the library's aim solvers behind a JSON file (docs/cli.md).</summary>
    internal static class AimCommand
    {
        public static string Run(string json)
        {
            throw new UsageError("aim is not available yet: the library's aim solvers are not in this build");
        }
    }
}
