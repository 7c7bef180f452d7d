using System;

namespace MagnusBall.Tests
{
    /// <summary>
    /// Measures what a piece of code allocates per run once the runtime's one-time work is done, for the
    /// allocation tests (<c>Assert.That(Allocation.SteadyStateBytes(run), Is.EqualTo(0))</c>). Also compiled into
    /// MagnusBall.UnityScripts.Tests (linked from its project file).
    /// </summary>
    /// <remarks>
    /// <para>
    /// A runtime allocates on the calling thread while it JIT-compiles a method on its first call (Mono 6.8 does),
    /// runs static constructors, loads types, replaces a long-running loop on the stack (CoreCLR's on-stack
    /// replacement, after about 1,000 iterations) or promotes a method to the next tier. That is not the measured
    /// code's allocation, and a single warm-up does not always absorb it: a 100-step warm-up before a 2,000-step
    /// measurement let 5,056 B of it into the measurement once in CI, and one warm-up solve let 2,280 B in once.
    /// </para>
    /// <para>
    /// So the identical call runs once as a warm-up (not a shorter one: a loop only reaches on-stack replacement
    /// when it runs as long), then up to <see cref="MeasuredRuns"/> times measured, and the fewest bytes of those
    /// runs are returned. One-time work happens once, so it can spoil one run but not every run; an allocation
    /// in the measured code's own path happens on every run, so it shows in every run and in the result, and
    /// <c>Is.EqualTo(0)</c> still fails for it. The measurement stops at the first run that allocates nothing.
    /// </para>
    /// <para>
    /// Every run must do the same real work: code that advances a state (a stepper, driver or batch) resets it to
    /// the same start inside <c>measured</c> (or in <c>prepare</c>, when the reset itself allocates), so a later
    /// run does not find the flight over and do nothing. Create the delegate (and the closure it captures) before
    /// the call: that allocates, invoking it does not.
    /// </para>
    /// </remarks>
    internal static class Allocation
    {
        /// <summary>The most measured runs after the warm-up.</summary>
        internal const int MeasuredRuns = 3;

        /// <summary>
        /// Runs <paramref name="measured"/> once unmeasured, then up to <see cref="MeasuredRuns"/> times measured, and
        /// returns the fewest bytes the current thread allocated in one measured run (see the remarks on the class).
        /// </summary>
        /// <param name="measured">The code whose allocation is asserted; each run must do the same work.</param>
        /// <returns>The fewest bytes allocated by one measured run; 0 as soon as one run allocates nothing.</returns>
        internal static long SteadyStateBytes(Action measured) => SteadyStateBytes(null, measured);

        /// <summary>
        /// As <see cref="SteadyStateBytes(Action)"/>, with <paramref name="prepare"/> run unmeasured before every run
        /// (the warm-up too), for a reset that allocates by design (a launch that builds a new driver).
        /// </summary>
        /// <param name="prepare">Unmeasured set-up before each run (null: none).</param>
        /// <param name="measured">The code whose allocation is asserted; each run must do the same work.</param>
        /// <returns>The fewest bytes allocated by one measured run; 0 as soon as one run allocates nothing.</returns>
        internal static long SteadyStateBytes(Action? prepare, Action measured)
        {
            if (measured == null)
            {
                throw new ArgumentNullException(nameof(measured));
            }

            prepare?.Invoke();
            measured(); // warm-up: the identical call
            long fewest = long.MaxValue;
            for (int run = 0; run < MeasuredRuns && fewest > 0; run++)
            {
                prepare?.Invoke();
                long before = GC.GetAllocatedBytesForCurrentThread();
                measured();
                long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
                fewest = Math.Min(fewest, bytes);
            }

            return fewest;
        }
    }
}
