// The MemberZero example of manual §3.3.2, compiled unchanged against the
// legacy header. The manual leaves Init/Close/DoYourJob and the end of main
// ("....") to the reader; they are completed below the verbatim part.
#include <dcdt.h>

#include <cstdio>
#include <cstring>

// ---- verbatim from the manual ---------------------------------------------
class MemberZero : public DCDT_Member {  
  
public:  
  
MemberZero (DCDT_Agora*);  
MemberZero();  
void Init();  
void Close();  
void DoYourJob(int);  
  
};  
  
MemberZero::MemberZero (DCDT_Agora* agora)  
:DCDT_Member(agora,20000){};
// ---- end of the verbatim part ----------------------------------------------

void MemberZero::Init() { SubscribeMsgType(MSG_FROM_VISION, DCDT_ALL_MSG); }

void MemberZero::Close() { std::printf("MemberZero closed\n"); }

void MemberZero::DoYourJob(int n) {
  DCDT_Msg* msg = CreateMsg(MSG_TO_BRIAN);
  const char text[] = "<message time=\"0\"/>";
  msg->SetPayload(text, static_cast<int>(std::strlen(text)));
  std::printf("MemberZero job %d: agora %d shares type %d, %d bytes\n", n, msg->ReadAgoraID(), msg->ReadType(),
              msg->ReadPayloadLen());
  ShareMsg(msg);
  Shutdown();  // one 20 s period is enough for a test
}

int main(int argc, char **argv) {
    (void)argc;
    (void)argv;

    DCDT_Agora *agora;
    MemberZero *member0;

    agora = new DCDT_Agora("dcdt.conf");

    member0 = new MemberZero(agora);
    agora->AddMember(member0);
    agora->ActivateMember(member0);

    agora->LetsWork();
    std::printf("LetsWork returned\n");
    delete member0;
    delete agora;
    return 0;
}
