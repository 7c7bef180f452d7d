using Microsoft.AspNetCore.Components.Web;
using Microsoft.AspNetCore.Components.WebAssembly.Hosting;

namespace MagnusBall.Playground
{
    /// <summary>The playground's entry point: the one page (Pages/Home.razor) and nothing else.</summary>
    public static class Program
    {
        /// <summary>Starts the app in the browser.</summary>
        public static System.Threading.Tasks.Task Main(string[] args)
        {
            WebAssemblyHostBuilder builder = WebAssemblyHostBuilder.CreateDefault(args);
            builder.RootComponents.Add<App>("#app");
            builder.RootComponents.Add<HeadOutlet>("head::after");
            return builder.Build().RunAsync();
        }
    }
}
