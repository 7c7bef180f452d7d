// Compiled by tools/ratios-mono.sh with Mono's compiler (mcs) against MagnusBall.Ratios.dll; runs the "ratios" mode under Mono.
public static class Launcher
{
    public static int Main(string[] args)
    {
        int rounds = args.Length > 0 ? int.Parse(args[0], System.Globalization.CultureInfo.InvariantCulture) : 5;
        double seconds = args.Length > 1 ? double.Parse(args[1], System.Globalization.CultureInfo.InvariantCulture) : 0.25;
        return MagnusBall.Benchmarks.Ratios.Run(rounds, seconds);
    }
}
