using System;
using System.Collections.Generic;
using System.Security;
using NUnit.Framework.Api;
using NUnit.Framework.Interfaces;
using NUnit.Framework.Internal;

namespace MagnusBall.Tests.Mono
{
    /// <summary>
    /// Runs this assembly's NUnit tests in-process through NUnit's own runner API (what NUnitLite does): the
    /// console runner this project can restore (3.15) does not drive NUnit 4. Arguments, if any, are regular
    /// expressions on full test names (any match runs). Prints every failure and a closing "N passed, N failed" line;
    /// exits 1 on any failure or when nothing passed.
    /// </summary>
    public static class MonoTestMain
    {
        /// <summary>Entry point.</summary>
        public static int Main(string[] args)
        {
            var runner = new NUnitTestAssemblyRunner(new DefaultTestAssemblyBuilder());
            runner.Load(typeof(MonoTestMain).Assembly, new Dictionary<string, object>());
            ITestFilter filter = args.Length == 0
                ? TestFilter.Empty
                : TestFilter.FromXml("<filter><or>" + string.Concat(Array.ConvertAll(args, a => "<test re=\"1\">" + SecurityElement.Escape(a) + "</test>")) + "</or></filter>");
            ITestResult result = runner.Run(TestListener.NULL, filter);
            Report(result);
            Console.WriteLine($"mono: {result.PassCount} passed, {result.FailCount} failed, {result.SkipCount + result.InconclusiveCount} skipped");
            return result.FailCount == 0 && result.PassCount > 0 ? 0 : 1;
        }

        private static void Report(ITestResult result)
        {
            bool failedHere = result.ResultState.Status == TestStatus.Failed
                && (!result.Test.IsSuite || result.ResultState.Site == FailureSite.SetUp || result.ResultState.Site == FailureSite.TearDown);
            if (failedHere)
            {
                Console.WriteLine($"FAILED {result.FullName}: {result.Message}");
                Console.WriteLine(result.StackTrace);
            }

            foreach (ITestResult child in result.Children)
            {
                Report(child);
            }
        }
    }
}
